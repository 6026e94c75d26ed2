// The CPU backend as a policy the stages are templates on: its buffers and its primitives.
// backend/cuda/cuda_backend.cuh is the same shape for the GPU.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "backend/buffer.hpp"
#include "backend/cpu_parallel.hpp"

namespace sph::backend {

struct CpuBackend {
  static constexpr const char* kName = "cpu";
  static constexpr bool kHostMemory = true;  // its buffers are host memory, read in place
  static constexpr bool kBatches = true;  // the passes take neighbours a SIMD batch at a time
  template <class T>
  using Buffer = backend::Buffer<T>;

  template <class F>
  static void forEach(std::size_t n, F f) {
    backend::forEach(n, f);
  }
  template <class T, class Map, class Combine>
  static T reduce(std::size_t n, T identity, Map map, Combine combine) {
    return backend::reduce(n, identity, map, combine);
  }
  struct SortScratch {};  // the CPU sort needs none that lives across steps
  static void countingSort(const std::uint32_t* keys, std::size_t n, std::uint32_t binCount,
                           std::uint32_t* order, std::uint32_t* binStart, SortScratch&) {
    backend::countingSort(keys, n, binCount, order, binStart);
  }
  template <class T>
  static void gather(const T* in, const std::uint32_t* order, std::size_t n, T* out) {
    backend::gather(in, order, n, out);
  }
  // Host ↔ backend memory.
  template <class T>
  static void upload(Buffer<T>& to, const T* from, std::size_t n) {
    to.resize(n);
    std::copy(from, from + n, to.data());
  }
  template <class T>
  static void download(const Buffer<T>& from, T* to, std::size_t n) {
    std::copy(from.data(), from.data() + n, to);
  }
  template <class T>
  static T read(const T* element) {
    return *element;
  }
};

}  // namespace sph::backend
