// queryGpus() of a build without the CUDA backend.
#include "sph/devices.hpp"

namespace sph {

GpuReport queryGpus() {
  GpuReport report;
  report.reason =
      "this sph was built without the CUDA backend (SPH_WITH_CUDA=OFF, or no nvcc when it was "
      "configured)";
  return report;
}

}  // namespace sph
