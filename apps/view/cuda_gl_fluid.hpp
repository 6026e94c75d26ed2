// Draws a CUDA simulation's fluid without a host copy (CUDA–OpenGL interop): the renderer's
// position and colour buffers are registered with CUDA once; each frame they are mapped,
// Simulation::writeFluidForDrawing writes positions and the quantity shown, a kernel colours
// the fluid through a FluidColourTable, and unmapping orders it all before the draw.
#pragma once

#include <cstddef>
#include <memory>

#include "fluid_colour_table.hpp"
#include "particle_renderer.hpp"
#include "sph/simulation.hpp"

namespace sph::view {

// Whether this build has the CUDA–OpenGL path (the CUDA backend and the viewer).
bool cudaGlInteropBuilt();

class CudaGlFluid {
 public:
  // Registers the renderer's buffers as they are now (reserve room first; growing them later
  // needs a new CudaGlFluid). Throws std::runtime_error naming the CUDA call when they cannot
  // be registered: no CUDA in this build, or an OpenGL context that is not on a CUDA device.
  explicit CudaGlFluid(const render::ParticleRenderer& renderer);
  ~CudaGlFluid();
  CudaGlFluid(const CudaGlFluid&) = delete;
  CudaGlFluid& operator=(const CudaGlFluid&) = delete;

  // Writes the fluid of `sim` (on the CUDA backend) into the buffers' first entries, coloured by
  // `table` from `quantity`; returns how many particles it wrote.
  std::size_t write(const Simulation& sim, FluidQuantity quantity,
                    const render::FluidColourTable& table);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph::view
