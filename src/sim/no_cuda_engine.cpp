// makeCudaEngine of a build without the CUDA backend.
#include "sim/fluid_engine.hpp"
#include "sph/devices.hpp"
#include "sph/error.hpp"

namespace sph::sim {

std::unique_ptr<FluidEngine> makeCudaEngine(const EngineSetup&, int) {
  throw InputError("--backend cuda: " + queryGpus().reason);
}

}  // namespace sph::sim
