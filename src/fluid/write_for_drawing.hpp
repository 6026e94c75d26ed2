// Stage (outside the step, for a renderer): the fluid's positions, one quantity per particle and
// the ids, in the engine's current order, into arrays in the backend's memory.
#pragma once

#include <cstdint>

#include "fluid/particles.hpp"
#include "sph/fluid_draw.hpp"

namespace sph::fluid {

template <class B>
void writeForDrawing(const FluidParticles<B>& fluid, Vec4* position, float* value,
                     std::uint32_t* id, FluidQuantity quantity, float surfaceThreshold) {
  const Vec4* x = fluid.position.data();
  const Vec4* v = fluid.velocity.data();
  const float* density = fluid.density.data();
  const float* pressure = fluid.pressure.data();
  const Vec4* acceleration = fluid.acceleration.data();
  const std::uint32_t* ids = fluid.id.data();
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        position[i] = Vec4{x[i].x, x[i].y, x[i].z, 1.0f};
        if (id) id[i] = ids[i];
        if (!value) return;
        switch (quantity) {
          case FluidQuantity::Density:
            value[i] = density[i];
            break;
          case FluidQuantity::Pressure:
            value[i] = pressure[i];
            break;
          case FluidQuantity::Speed:
            value[i] = length(xyz(v[i]));
            break;
          case FluidQuantity::Surface:
            value[i] = acceleration[i].w > surfaceThreshold ? 1.0f : 0.0f;
            break;
          case FluidQuantity::None:
            break;
        }
      });
}

}  // namespace sph::fluid
