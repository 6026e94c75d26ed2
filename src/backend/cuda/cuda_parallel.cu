#include <thrust/execution_policy.h>
#include <thrust/scan.h>
#include <cub/device/device_radix_sort.cuh>

#include "backend/cuda/cuda_parallel.cuh"

namespace sph::backend::cuda {

namespace {

__global__ void histogramKernel(const std::uint32_t* keys, std::size_t n, std::uint32_t* counts) {
  const std::size_t i = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) atomicAdd(&counts[keys[i]], 1u);
}

__global__ void iotaKernel(std::uint32_t* out, std::size_t n) {
  const std::size_t i = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) out[i] = static_cast<std::uint32_t>(i);
}

int significantBits(std::uint32_t binCount) {
  int bits = 1;
  while (bits < 32 && (std::uint64_t{1} << bits) < binCount) ++bits;
  return bits;
}

}  // namespace

std::uint32_t exclusiveScan(std::uint32_t* data, std::size_t n) {
  if (n == 0) return 0;
  std::uint32_t last = 0;
  SPH_CUDA_CHECK(cudaMemcpy(&last, data + n - 1, sizeof last, cudaMemcpyDeviceToHost));
  thrust::exclusive_scan(thrust::device, data, data + n, data);
  SPH_CUDA_CHECK(cudaGetLastError());
  std::uint32_t lastStart = 0;
  SPH_CUDA_CHECK(cudaMemcpy(&lastStart, data + n - 1, sizeof lastStart, cudaMemcpyDeviceToHost));
  return lastStart + last;
}

void countingSort(const std::uint32_t* keys, std::size_t n, std::uint32_t binCount,
                  std::uint32_t* order, std::uint32_t* binStart, SortScratch& scratch) {
  SPH_CUDA_CHECK(cudaMemset(binStart, 0, (binCount + 1) * sizeof(std::uint32_t)));
  if (n == 0) return;
  histogramKernel<<<blocksFor(n), kBlockSize>>>(keys, n, binStart);
  SPH_CUDA_CHECK(cudaGetLastError());
  // binStart[binCount] holds 0 before the scan, so the scan leaves the total there.
  exclusiveScan(binStart, binCount + 1);

  scratch.sortedKeys.resize(n);
  scratch.indices.resize(n);
  iotaKernel<<<blocksFor(n), kBlockSize>>>(scratch.indices.data(), n);
  SPH_CUDA_CHECK(cudaGetLastError());
  const int bits = significantBits(binCount);
  std::size_t scratchBytes = 0;
  SPH_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, scratchBytes, keys,
                                                 scratch.sortedKeys.data(), scratch.indices.data(),
                                                 order, n, 0, bits));
  scratch.cub.resize(scratchBytes);
  SPH_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(scratch.cub.data(), scratchBytes, keys,
                                                 scratch.sortedKeys.data(), scratch.indices.data(),
                                                 order, n, 0, bits));
}

}  // namespace sph::backend::cuda
