// Handing the fluid to a renderer without a host copy: Simulation::writeFluidForDrawing writes
// positions and one quantity per particle into arrays in the backend's own memory. On the CUDA
// backend those are device pointers, such as an OpenGL buffer mapped through CUDA–OpenGL
// interop; on the CPU they are host pointers.
#pragma once

#include <cstddef>
#include <cstdint>

namespace sph {

// The quantity written beside each position.
enum class FluidQuantity : std::uint8_t {
  None,      // nothing is written to `value`
  Density,   // kg/m³
  Pressure,  // Pa
  Speed,     // m/s
  Surface,   // 1 on the free surface (Meteer 2011, eqs. 11-12), else 0
};

struct FluidDrawTarget {
  float* position = nullptr;    // x, y, z, 1 per particle; 16-byte aligned
  float* value = nullptr;       // the quantity per particle; may be null when quantity is None
  std::uint32_t* id = nullptr;  // the particle's stable id; may be null
  std::size_t capacity = 0;     // particles each array holds
  FluidQuantity quantity = FluidQuantity::None;
};

}  // namespace sph
