#include "backend/cpu_backend.hpp"
#include "sim/cpu_stage_instances.hpp"
#include "sim/engine_impl.hpp"

namespace sph::sim {

std::unique_ptr<FluidEngine> makeCpuEngine(const EngineSetup& setup) {
  return std::make_unique<EngineImpl<backend::CpuBackend>>(setup);
}

}  // namespace sph::sim
