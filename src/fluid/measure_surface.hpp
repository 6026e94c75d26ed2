// Stage (outside the step, when a frame or statistics are taken): the colour field's gradient
// |∇c| at the particles' present positions (seed 1 eqs. 11-12, C_j = 1), into acceleration.w;
// a particle is on the free surface where it passes the threshold. Walls count as filled space.
// Reads the neighbour lists of the last density pass (the cells for a particle with too many),
// so it needs a step taken; the pairs are those of that step, their distances today's.
#pragma once

#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/parameters.hpp"
#include "fluid/particles.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

namespace detail {

template <class B, class Kernels>
void measureSurfaceWith(FluidParticles<B>& fluid, const Grid<B>& grid,
                        const BoundaryParticles<B>& boundary, const FluidParameters& params,
                        Kernels kernels) {
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const GridSpec wallGrid = boundary.grid;
  const std::uint32_t* wallCellStart = boundary.cellStart.data();
  const Vec4* position = fluid.position.data();
  const Vec4* state = fluid.pressureState.data();  // y: 1/ρ
  const Vec4* wall = boundary.position.data();     // w: volume
  Vec4* acceleration = fluid.acceleration.data();
  const std::uint32_t stride = fluid.neighborStride;
  const std::uint32_t* neighbors = fluid.neighbors.data();
  const std::uint32_t* neighborCount = fluid.neighborCount.data();
  const float h2 = params.h * params.h;
  const float mass = params.mass;

  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 xi = xyz(position[i]);
        Vec3 gradient{0.0f, 0.0f, 0.0f};
        auto add = [&](Vec3 rij, float volumeJ) {
          const float r2 = lengthSquared(rij);
          if (r2 >= h2 || r2 <= 0.0f) return;
          gradient += rij * (volumeJ * kernels.colourGradFactor(realSqrt(r2)));
        };
        auto fluidPair = [&](std::uint32_t j) {
          if (j != i) add(xi - xyz(readOnly(position + j)), mass * readOnly(state + j).y);
        };
        const std::uint32_t count = neighborCount[i];
        if (count != kNeighborOverflow) {
          const std::uint32_t* list = neighbors + i * stride;
          for (std::uint32_t k = 0; k < count; ++k) fluidPair(readOnly(list + k));
        } else {
          forEachNeighbor(spec, cellStart, xi, fluidPair);
        }
        if (wallCellStart != nullptr) {
          forEachNeighbor(wallGrid, wallCellStart, xi, [&](std::uint32_t b) {
            const Vec4 xb = readOnly(wall + b);
            add(xi - xyz(xb), xb.w);
          });
        }
        acceleration[i].w = length(gradient);
      });
}

}  // namespace detail

template <class B>
void measureSurface(FluidParticles<B>& fluid, const Grid<B>& grid,
                    const BoundaryParticles<B>& boundary, const FluidParameters& params) {
  // The kernel set is a template argument of a named function: nvcc allows no device lambda
  // inside a generic one.
  withKernels(params, [&](auto kernels) {
    detail::measureSurfaceWith(fluid, grid, boundary, params, kernels);
  });
}

}  // namespace sph::fluid
