// An array in page-locked host memory, owned (RAII): the GPU copies into it asynchronously and
// at full bus speed, which pageable memory allows neither.
#pragma once

#include <cstddef>
#include <utility>

#include "backend/cuda/cuda_check.hpp"

namespace sph::backend::cuda {

template <class T>
class PinnedBuffer {
 public:
  PinnedBuffer() = default;
  ~PinnedBuffer() { release(); }
  PinnedBuffer(const PinnedBuffer&) = delete;
  PinnedBuffer& operator=(const PinnedBuffer&) = delete;

  // Keeps no contents.
  void resize(std::size_t n) {
    if (n > capacity_) {
      release();
      SPH_CUDA_CHECK(cudaMallocHost(reinterpret_cast<void**>(&data_), n * sizeof(T)));
      capacity_ = n;
    }
    size_ = n;
  }
  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  void release() noexcept {
    if (data_ != nullptr) cudaFreeHost(data_);  // no throw from a destructor
    data_ = nullptr;
    capacity_ = size_ = 0;
  }

  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace sph::backend::cuda
