// sph info: what this binary was built with and what it can run on.
#include <cstdio>

#include "commands.hpp"
#include "run_processes.hpp"
#include "sph/devices.hpp"
#include "sph/threads.hpp"

#ifndef SPH_VERSION
#define SPH_VERSION "unknown"
#endif
#ifndef SPH_BUILD_TYPE
#define SPH_BUILD_TYPE "unknown"
#endif

namespace sph::cli {

SimulationOptions simulationOptions(const std::string& backend, int device) {
  SimulationOptions options;
  options.backend =
      backend == "cuda" ? Backend::Cuda : (backend == "cpu" ? Backend::Cpu : Backend::Auto);
  options.device = device;
  return options;
}

void printGpus(std::FILE* out) {
  const GpuReport gpus = queryGpus();
  if (gpus.devices.empty()) std::fprintf(out, "  no GPU: %s\n", gpus.reason.c_str());
  for (const GpuDevice& d : gpus.devices) {
    std::fprintf(out, "  [%d] %s, compute capability %d.%d, %d SMs, %.1f GiB (%.1f GiB free)\n",
                 d.index, d.name.c_str(), d.computeMajor, d.computeMinor, d.multiprocessors,
                 double(d.totalMemory) / (1 << 30), double(d.freeMemory) / (1 << 30));
  }
}

int infoCommand() {
  std::printf("sph %s (%s build, %s)\n", SPH_VERSION, SPH_BUILD_TYPE, __VERSION__);
  std::printf("backends:\n");
#ifdef _OPENMP
  std::printf("  cpu   OpenMP %d, %d threads available\n", _OPENMP, threadCount());
#else
  std::printf("  cpu   serial (built without OpenMP)\n");
#endif
  const GpuReport gpus = queryGpus();
  if (!gpus.cudaBuilt) {
    std::printf("  cuda  not built: %s\n", gpus.reason.c_str());
  } else {
    std::printf("  cuda  built (--backend cuda, or auto when a GPU is present)\n");
  }
  std::printf("across processes:\n");
  std::printf("  mpi   %s\n", RunProcesses::built()
                                  ? "built (mpirun -np N sph run; OpenMPI, Zoltan)"
                                  : "not built (SPH_WITH_MPI=OFF or OpenMPI, Zoltan missing)");
  std::printf("graphics:\n");
  std::printf("  render  %s\n", rendererBuilt()
                                    ? "built (sph render, sph run --render; EGL offscreen)"
                                    : "not built (SPH_WITH_VIEWER=OFF or its libraries missing)");
  std::printf("  view    %s\n",
              viewerBuilt() ? "built (sph view; needs a display)"
                            : "not built (SPH_WITH_VIEWER=OFF or GLFW, Dear ImGui missing)");
  std::printf("devices:\n");
  printGpus(stdout);
  return kExitOk;
}

}  // namespace sph::cli
