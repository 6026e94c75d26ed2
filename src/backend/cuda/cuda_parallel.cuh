// The CUDA backend: the same primitives as backend/cpu_parallel.hpp, on the GPU, on the
// default stream. Per-particle functors are written once (SPH_LAMBDA) and launched here.
#pragma once

#include <cstddef>
#include <cstdint>

#include "backend/cuda/cuda_check.hpp"
#include "backend/cuda/device_buffer.hpp"

namespace sph::backend::cuda {

constexpr int kBlockSize = 256;

template <class F>
__global__ void forEachKernel(std::size_t n, F f) {
  const std::size_t i = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}

inline unsigned blocksFor(std::size_t n) {
  return static_cast<unsigned>((n + kBlockSize - 1) / kBlockSize);
}

// f(i) for every i in [0, n), one thread each.
template <class F>
void forEach(std::size_t n, F f) {
  if (n == 0) return;
  forEachKernel<<<blocksFor(n), kBlockSize>>>(n, f);
  SPH_CUDA_CHECK(cudaGetLastError());
}

// out[i] = in[order[i]].
template <class T>
void gather(const T* in, const std::uint32_t* order, std::size_t n, T* out) {
  forEach(n, [=] __device__(std::size_t i) { out[i] = in[order[i]]; });
}

// In place on device memory: data[i] = sum of data[0..i). Returns the total.
std::uint32_t exclusiveScan(std::uint32_t* data, std::size_t n);

// The radix sort's working memory, grown as needed and kept by the caller across calls.
struct SortScratch {
  DeviceBuffer<std::uint32_t> sortedKeys;
  DeviceBuffer<std::uint32_t> indices;
  DeviceBuffer<unsigned char> cub;
};

// Counting sort by key on device memory, as the CPU backend's: `order` (sorted position →
// original index; stable, by CUB's radix sort) and `binStart` (binCount + 1 entries, from an
// atomic histogram and a scan).
void countingSort(const std::uint32_t* keys, std::size_t n, std::uint32_t binCount,
                  std::uint32_t* order, std::uint32_t* binStart, SortScratch& scratch);

}  // namespace sph::backend::cuda
