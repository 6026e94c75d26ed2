#include "cuda_gl_fluid.hpp"

// The GL types cuda_gl_interop.h needs, from the loader the renderer uses.
#include <epoxy/gl.h>
// clang-format off
#include <cuda_gl_interop.h>
#include <cuda_runtime.h>
// clang-format on

#include <cstdint>
#include <stdexcept>
#include <string>

namespace sph::view {

namespace {

void check(cudaError_t status, const char* call) {
  if (status != cudaSuccess)
    throw std::runtime_error(std::string("CUDA–OpenGL interop: ") + call + ": " +
                             cudaGetErrorString(status));
}

#define SPH_INTEROP_CHECK(call) check((call), #call)

__global__ void colourFluid(const float* value, std::size_t n, const uchar4* table, float lo,
                            float hi, uchar4* rgba) {
  const std::size_t i = std::size_t(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i >= n) return;
  rgba[i] = table[render::fluidColourEntry(lo, hi, value ? value[i] : 0.0f)];
}

}  // namespace

bool cudaGlInteropBuilt() {
  return true;
}

struct CudaGlFluid::Impl {
  cudaGraphicsResource* resources[2] = {nullptr, nullptr};  // positions, colours
  std::size_t capacity = 0;
  float* value = nullptr;   // the quantity shown, per particle
  uchar4* table = nullptr;  // FluidColourTable::kEntries colours
  render::FluidColourTable uploaded;
  bool anyUploaded = false;

  ~Impl() {
    // Destructors do not throw: a failure to release at exit changes nothing drawn.
    for (cudaGraphicsResource* r : resources)
      if (r) cudaGraphicsUnregisterResource(r);
    cudaFree(value);
    cudaFree(table);
  }
};

CudaGlFluid::CudaGlFluid(const render::ParticleRenderer& renderer)
    : impl_(std::make_unique<Impl>()) {
  const auto positions = renderer.positionBuffer();
  const auto colours = renderer.colourBuffer();
  impl_->capacity = positions.capacity;
  SPH_INTEROP_CHECK(cudaGraphicsGLRegisterBuffer(&impl_->resources[0], positions.name,
                                                 cudaGraphicsRegisterFlagsNone));
  SPH_INTEROP_CHECK(cudaGraphicsGLRegisterBuffer(&impl_->resources[1], colours.name,
                                                 cudaGraphicsRegisterFlagsNone));
  SPH_INTEROP_CHECK(cudaMalloc(&impl_->value, impl_->capacity * sizeof(float)));
  SPH_INTEROP_CHECK(cudaMalloc(&impl_->table, render::FluidColourTable::kEntries * sizeof(uchar4)));
}

CudaGlFluid::~CudaGlFluid() = default;

std::size_t CudaGlFluid::write(const Simulation& sim, FluidQuantity quantity,
                               const render::FluidColourTable& table) {
  Impl& s = *impl_;
  if (!s.anyUploaded || table.rgba != s.uploaded.rgba) {
    SPH_INTEROP_CHECK(
        cudaMemcpy(s.table, table.rgba.data(), table.rgba.size(), cudaMemcpyHostToDevice));
    s.uploaded = table;
    s.anyUploaded = true;
  }
  SPH_INTEROP_CHECK(cudaGraphicsMapResources(2, s.resources, 0));
  std::size_t written = 0;
  try {
    void* positions = nullptr;
    void* colours = nullptr;
    std::size_t bytes = 0;
    SPH_INTEROP_CHECK(cudaGraphicsResourceGetMappedPointer(&positions, &bytes, s.resources[0]));
    SPH_INTEROP_CHECK(cudaGraphicsResourceGetMappedPointer(&colours, &bytes, s.resources[1]));
    FluidDrawTarget target;
    target.position = static_cast<float*>(positions);
    target.value = s.value;
    target.capacity = s.capacity;
    target.quantity = quantity;
    written = sim.writeFluidForDrawing(target);
    constexpr unsigned kBlock = 256;
    if (written > 0) {
      const auto blocks = unsigned((written + kBlock - 1) / kBlock);
      colourFluid<<<blocks, kBlock>>>(quantity == FluidQuantity::None ? nullptr : s.value, written,
                                      s.table, table.lo, table.hi, static_cast<uchar4*>(colours));
      SPH_INTEROP_CHECK(cudaGetLastError());
    }
  } catch (...) {
    cudaGraphicsUnmapResources(2, s.resources, 0);
    throw;
  }
  // Unmapping waits for the kernels on the default stream before OpenGL reads the buffers.
  SPH_INTEROP_CHECK(cudaGraphicsUnmapResources(2, s.resources, 0));
  return written;
}

}  // namespace sph::view
