// Frame output that does not stall the simulation (the 2021 CUDA SPH tutorial): a download
// copies the fluid's arrays on the GPU into a snapshot, in step order on the default stream,
// then from the snapshot into pinned host memory on a stream of its own, so the next steps run
// while the bytes cross the bus. Only take() waits.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "backend/cuda/cuda_backend.cuh"
#include "backend/cuda/pinned_buffer.hpp"
#include "sim/engine_impl.hpp"

namespace sph::sim {

namespace cudadl {

using backend::CudaBackend;
template <class T>
using DeviceBuffer = backend::cuda::DeviceBuffer<T>;
template <class T>
using PinnedBuffer = backend::cuda::PinnedBuffer<T>;

// One download in flight: its snapshot, its pinned copy and the event that ends the copy.
struct Slot {
  DeviceBuffer<std::uint32_t> id;
  DeviceBuffer<Vec4> position, velocity, acceleration;
  DeviceBuffer<float> density, pressure;
  PinnedBuffer<std::uint32_t> hostId;
  PinnedBuffer<Vec4> hostPosition, hostVelocity, hostAcceleration;
  PinnedBuffer<float> hostDensity, hostPressure;
  cudaEvent_t snapshotTaken = nullptr;
  cudaEvent_t copied = nullptr;
  std::size_t count = 0;

  Slot() {
    SPH_CUDA_CHECK(cudaEventCreateWithFlags(&snapshotTaken, cudaEventDisableTiming));
    SPH_CUDA_CHECK(cudaEventCreateWithFlags(&copied, cudaEventDisableTiming));
  }
  ~Slot() {
    cudaEventDestroy(snapshotTaken);  // no throw from a destructor
    cudaEventDestroy(copied);
  }
  Slot(const Slot&) = delete;
  Slot& operator=(const Slot&) = delete;
};

template <class T>
void snapshot(const DeviceBuffer<T>& from, DeviceBuffer<T>& to, std::size_t n) {
  to.resize(n);
  SPH_CUDA_CHECK(cudaMemcpyAsync(to.data(), from.data(), n * sizeof(T), cudaMemcpyDeviceToDevice,
                                 cudaStreamLegacy));
}

template <class T>
void copyOut(const DeviceBuffer<T>& from, PinnedBuffer<T>& to, std::size_t n, cudaStream_t stream) {
  to.resize(n);
  SPH_CUDA_CHECK(
      cudaMemcpyAsync(to.data(), from.data(), n * sizeof(T), cudaMemcpyDeviceToHost, stream));
}

template <class T>
std::vector<T> toVector(const PinnedBuffer<T>& from, std::size_t n) {
  return std::vector<T>(from.data(), from.data() + n);
}

}  // namespace cudadl

// The slots of one engine, reused: a slot is busy from beginDownload until its take().
class DownloadStaging {
 public:
  DownloadStaging() {
    // Non-blocking: the copies must not wait for, nor hold up, the steps' kernels on the
    // legacy default stream.
    SPH_CUDA_CHECK(cudaStreamCreateWithFlags(&copyStream_, cudaStreamNonBlocking));
  }
  ~DownloadStaging() { cudaStreamDestroy(copyStream_); }
  DownloadStaging(const DownloadStaging&) = delete;
  DownloadStaging& operator=(const DownloadStaging&) = delete;

  std::unique_ptr<cudadl::Slot> acquire() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (free_.empty()) return std::make_unique<cudadl::Slot>();
    std::unique_ptr<cudadl::Slot> slot = std::move(free_.back());
    free_.pop_back();
    return slot;
  }
  void release(std::unique_ptr<cudadl::Slot> slot) {
    std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(std::move(slot));
  }
  cudaStream_t copyStream() const { return copyStream_; }

 private:
  cudaStream_t copyStream_ = nullptr;
  std::mutex mutex_;
  std::vector<std::unique_ptr<cudadl::Slot>> free_;
};

class CudaPendingParticles final : public PendingParticles {
 public:
  CudaPendingParticles(std::shared_ptr<DownloadStaging> staging, std::unique_ptr<cudadl::Slot> slot)
      : staging_(std::move(staging)), slot_(std::move(slot)) {}
  ~CudaPendingParticles() override {
    if (!slot_) return;
    cudaEventSynchronize(slot_->copied);  // the copy must end before the slot is reused
    staging_->release(std::move(slot_));
  }

  HostParticles take() override {
    SPH_CUDA_CHECK(cudaEventSynchronize(slot_->copied));
    const std::size_t n = slot_->count;
    HostParticles h;
    h.id = cudadl::toVector(slot_->hostId, n);
    h.position = cudadl::toVector(slot_->hostPosition, n);
    h.velocity = cudadl::toVector(slot_->hostVelocity, n);
    h.density = cudadl::toVector(slot_->hostDensity, n);
    h.pressure = cudadl::toVector(slot_->hostPressure, n);
    h.acceleration = cudadl::toVector(slot_->hostAcceleration, n);
    staging_->release(std::move(slot_));
    return h;
  }

 private:
  std::shared_ptr<DownloadStaging> staging_;
  std::unique_ptr<cudadl::Slot> slot_;
};

template <>
inline std::unique_ptr<PendingParticles> beginParticleDownload<backend::CudaBackend>(
    const fluid::FluidParticles<backend::CudaBackend>& fluid,
    std::shared_ptr<DownloadStaging>& staging) {
  if (!staging) staging = std::make_shared<DownloadStaging>();
  std::unique_ptr<cudadl::Slot> slot = staging->acquire();
  const std::size_t n = fluid.count;
  slot->count = n;
  cudadl::snapshot(fluid.id, slot->id, n);
  cudadl::snapshot(fluid.position, slot->position, n);
  cudadl::snapshot(fluid.velocity, slot->velocity, n);
  cudadl::snapshot(fluid.density, slot->density, n);
  cudadl::snapshot(fluid.pressure, slot->pressure, n);
  cudadl::snapshot(fluid.acceleration, slot->acceleration, n);
  SPH_CUDA_CHECK(cudaEventRecord(slot->snapshotTaken, cudaStreamLegacy));
  const cudaStream_t stream = staging->copyStream();
  SPH_CUDA_CHECK(cudaStreamWaitEvent(stream, slot->snapshotTaken, 0));
  cudadl::copyOut(slot->id, slot->hostId, n, stream);
  cudadl::copyOut(slot->position, slot->hostPosition, n, stream);
  cudadl::copyOut(slot->velocity, slot->hostVelocity, n, stream);
  cudadl::copyOut(slot->density, slot->hostDensity, n, stream);
  cudadl::copyOut(slot->pressure, slot->hostPressure, n, stream);
  cudadl::copyOut(slot->acceleration, slot->hostAcceleration, n, stream);
  SPH_CUDA_CHECK(cudaEventRecord(slot->copied, stream));
  return std::make_unique<CudaPendingParticles>(staging, std::move(slot));
}

}  // namespace sph::sim
