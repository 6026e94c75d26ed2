// The CUDA backend as a policy the stages are templates on (see backend/cpu_backend.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include "backend/cuda/cuda_parallel.cuh"
#include "backend/cuda/cuda_reduce.cuh"
#include "backend/cuda/device_buffer.hpp"

namespace sph::backend {

struct CudaBackend {
  static constexpr const char* kName = "cuda";
  static constexpr bool kHostMemory = false;
  static constexpr bool kBatches = false;  // one thread per particle instead
  template <class T>
  using Buffer = cuda::DeviceBuffer<T>;

  template <class F>
  static void forEach(std::size_t n, F f) {
    cuda::forEach(n, f);
  }
  template <class T, class Map, class Combine>
  static T reduce(std::size_t n, T identity, Map map, Combine combine) {
    return cuda::reduce(n, identity, map, combine);
  }
  using SortScratch = cuda::SortScratch;  // kept across steps: no allocation per step
  static void countingSort(const std::uint32_t* keys, std::size_t n, std::uint32_t binCount,
                           std::uint32_t* order, std::uint32_t* binStart, SortScratch& scratch) {
    cuda::countingSort(keys, n, binCount, order, binStart, scratch);
  }
  template <class T>
  static void gather(const T* in, const std::uint32_t* order, std::size_t n, T* out) {
    cuda::gather(in, order, n, out);
  }
  template <class T>
  static void upload(Buffer<T>& to, const T* from, std::size_t n) {
    to.copyFromHost(from, n);
  }
  template <class T>
  static void download(const Buffer<T>& from, T* to, std::size_t n) {
    from.copyToHost(to, n);
  }
  template <class T>
  static T read(const T* element) {
    T value;
    SPH_CUDA_CHECK(cudaMemcpy(&value, element, sizeof(T), cudaMemcpyDeviceToHost));
    return value;
  }
};

}  // namespace sph::backend
