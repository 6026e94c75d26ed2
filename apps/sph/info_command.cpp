// sph info: what this binary was built with and what it can run on.
#include <cstdio>

#include "backend/cpu_parallel.hpp"
#include "commands.hpp"
#include "sph/devices.hpp"

#ifndef SPH_VERSION
#define SPH_VERSION "unknown"
#endif
#ifndef SPH_BUILD_TYPE
#define SPH_BUILD_TYPE "unknown"
#endif

namespace sph::cli {

bool checkBackend(const std::string& backend) {
  if (backend != "cuda") return true;
  const GpuReport gpus = queryGpus();
  if (!gpus.cudaBuilt) {
    std::fprintf(stderr, "error: --backend cuda: %s; use --backend cpu or auto\n",
                 gpus.reason.c_str());
  } else if (gpus.devices.empty()) {
    std::fprintf(stderr, "error: --backend cuda: no GPU: %s; use --backend cpu or auto\n",
                 gpus.reason.c_str());
  } else {
    std::fprintf(stderr,
                 "error: --backend cuda: this version runs the fluid stages on the CPU only; "
                 "the CUDA primitives are built but the GPU engine is not yet; use --backend "
                 "cpu or auto\n");
  }
  return false;
}

int infoCommand() {
  std::printf("sph %s (%s build, %s)\n", SPH_VERSION, SPH_BUILD_TYPE, __VERSION__);
  std::printf("backends:\n");
#ifdef _OPENMP
  std::printf("  cpu   OpenMP %d, %d threads available\n", _OPENMP, backend::threadCount());
#else
  std::printf("  cpu   serial (built without OpenMP)\n");
#endif
  const GpuReport gpus = queryGpus();
  if (!gpus.cudaBuilt) {
    std::printf("  cuda  not built: %s\n", gpus.reason.c_str());
  } else {
    std::printf("  cuda  primitives built (the fluid stages run on the CPU in this version)\n");
  }
  std::printf("devices:\n");
  if (gpus.devices.empty()) {
    std::printf("  no GPU: %s\n", gpus.reason.c_str());
  }
  for (const GpuDevice& d : gpus.devices) {
    std::printf("  [%d] %s, compute capability %d.%d, %d SMs, %.1f GiB (%.1f GiB free)\n",
                d.index, d.name.c_str(), d.computeMajor, d.computeMinor, d.multiprocessors,
                double(d.totalMemory) / (1 << 30), double(d.freeMemory) / (1 << 30));
  }
  return kExitOk;
}

}  // namespace sph::cli
