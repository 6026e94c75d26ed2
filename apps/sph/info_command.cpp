// sph info: what this binary was built with and what it can run on.
#include <cstdio>

#include "backend/cpu_parallel.hpp"
#include "commands.hpp"

#ifndef SPH_VERSION
#define SPH_VERSION "unknown"
#endif
#ifndef SPH_BUILD_TYPE
#define SPH_BUILD_TYPE "unknown"
#endif

namespace sph::cli {

bool checkBackend(const std::string& backend) {
  if (backend == "cuda") {
    std::fprintf(stderr,
                 "error: --backend cuda: this sph was built without the CUDA backend; use "
                 "--backend cpu or auto (see `sph info`)\n");
    return false;
  }
  return true;
}

int infoCommand() {
  std::printf("sph %s (%s build, %s)\n", SPH_VERSION, SPH_BUILD_TYPE, __VERSION__);
  std::printf("backends:\n");
#ifdef _OPENMP
  std::printf("  cpu   OpenMP %d, %d threads available\n", _OPENMP, backend::threadCount());
#else
  std::printf("  cpu   serial (built without OpenMP)\n");
#endif
  std::printf("  cuda  not built in this binary (configure with -DSPH_WITH_CUDA=ON)\n");
  std::printf("devices: no GPU is used by this binary\n");
  return kExitOk;
}

}  // namespace sph::cli
