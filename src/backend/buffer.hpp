// An array the backend's per-particle code reads and writes. On the CPU it is host memory;
// the CUDA backend gives the same interface over device memory. Resizing does not preserve
// contents and does not initialise: every stage writes what it later reads.
#pragma once

#include <cstddef>
#include <memory>

namespace sph::backend {

template <class T>
class Buffer {
 public:
  Buffer() = default;
  explicit Buffer(std::size_t n) { resize(n); }

  void resize(std::size_t n) {
    if (n > capacity_) {
      data_.reset(new T[n]);
      capacity_ = n;
    }
    size_ = n;
  }
  // Keeps the first `n` elements; never reallocates.
  void shrink(std::size_t n) { size_ = n < size_ ? n : size_; }

  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  void swap(Buffer& other) noexcept {
    data_.swap(other.data_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
  }

 private:
  std::unique_ptr<T[]> data_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace sph::backend
