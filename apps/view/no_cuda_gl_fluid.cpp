// A build without the CUDA backend: the viewer always draws through host copies.
#include <stdexcept>

#include "cuda_gl_fluid.hpp"

namespace sph::view {

bool cudaGlInteropBuilt() {
  return false;
}

struct CudaGlFluid::Impl {};

CudaGlFluid::CudaGlFluid(const render::ParticleRenderer&) {
  throw std::runtime_error("CUDA–OpenGL interop: this build has no CUDA backend");
}

CudaGlFluid::~CudaGlFluid() = default;

std::size_t CudaGlFluid::write(const Simulation&, FluidQuantity, const render::FluidColourTable&) {
  return 0;
}

}  // namespace sph::view
