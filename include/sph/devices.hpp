// Which GPUs this build can use (`sph info`, `--backend auto`).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sph {

struct GpuDevice {
  int index = 0;
  std::string name;
  std::size_t totalMemory = 0;  // bytes
  std::size_t freeMemory = 0;   // bytes, when queried
  int computeMajor = 0;
  int computeMinor = 0;
  int multiprocessors = 0;
};

struct GpuReport {
  bool cudaBuilt = false;          // this binary has the CUDA backend
  std::vector<GpuDevice> devices;  // empty: see `reason`
  std::string reason;              // why there is no usable GPU
};

GpuReport queryGpus();

}  // namespace sph
