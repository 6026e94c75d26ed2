#include <cuda_runtime.h>

#include "sph/devices.hpp"

namespace sph {

GpuReport queryGpus() {
  GpuReport report;
  report.cudaBuilt = true;
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess) {
    report.reason = std::string("the CUDA runtime found no usable device: ") +
                    cudaGetErrorName(status) + " (" + cudaGetErrorString(status) + ")";
    return report;
  }
  if (count == 0) {
    report.reason = "the CUDA runtime reports no device";
    return report;
  }
  for (int i = 0; i < count; ++i) {
    cudaDeviceProp props{};
    if (cudaGetDeviceProperties(&props, i) != cudaSuccess) continue;
    GpuDevice device;
    device.index = i;
    device.name = props.name;
    device.totalMemory = props.totalGlobalMem;
    device.computeMajor = props.major;
    device.computeMinor = props.minor;
    device.multiprocessors = props.multiProcessorCount;
    if (cudaSetDevice(i) == cudaSuccess) {
      std::size_t freeBytes = 0, totalBytes = 0;
      if (cudaMemGetInfo(&freeBytes, &totalBytes) == cudaSuccess) device.freeMemory = freeBytes;
    }
    report.devices.push_back(device);
  }
  return report;
}

}  // namespace sph
