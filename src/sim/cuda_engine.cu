#include "backend/cuda/cuda_backend.cuh"
#include "sim/cuda_download.cuh"
#include "sim/engine_impl.hpp"
#include "sph/devices.hpp"
#include "sph/error.hpp"

namespace sph::sim {

std::unique_ptr<FluidEngine> makeCudaEngine(const EngineSetup& setup, int device) {
  const GpuReport gpus = queryGpus();
  if (gpus.devices.empty()) throw InputError("--backend cuda: no GPU: " + gpus.reason);
  if (device < 0 || device >= static_cast<int>(gpus.devices.size()))
    throw InputError("--device " + std::to_string(device) + ": expected 0 to " +
                     std::to_string(gpus.devices.size() - 1));
  SPH_CUDA_CHECK(cudaSetDevice(device));
  return std::make_unique<EngineImpl<backend::CudaBackend>>(setup);
}

}  // namespace sph::sim
