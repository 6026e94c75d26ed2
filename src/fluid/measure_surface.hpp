// Stage (outside the step, when a frame or statistics are taken): the colour field's gradient
// |∇c| at the particles' present positions (Meteer 2011, eqs. 11-12, C_j = 1), into acceleration.w;
// a particle is on the free surface where it passes the threshold. Walls count as filled space.
// Reads the neighbour lists of the last density pass (the cells for a particle with too many),
// so it needs a step taken; the pairs are those of that step, their distances today's.
#pragma once

#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

namespace detail {

template <class B, class Kernels>
void measureSurfaceWith(FluidParticles<B>& fluid, const Grid<B>& grid,
                        const BoundaryParticles<B>& boundary, const FluidParameters& params,
                        Kernels kernels) {
  const NeighborLists lists = neighborLists(fluid, grid);
  const WallCells walls = wallCells(boundary);
  const Vec4* position = fluid.position.data();
  const Vec4* state = fluid.pressureState.data();
  const Vec4* wall = boundary.position.data();  // w: volume ψ_b
  Vec4* acceleration = fluid.acceleration.data();
  const float h2 = params.h * params.h;
  const float mass = params.mass;
  const Periodicity periodic = params.periodic;

  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 xi = xyz(position[i]);
        const bool seam = nearSeam(periodic, xi);
        Vec3 gradient{0.0f, 0.0f, 0.0f};
        auto add = [&](Vec3 rij, float volume) {
          const float r2 = lengthSquared(rij);
          if (r2 >= h2 || r2 <= 0.0f) return;
          gradient += colourGradientTerm(kernels, makePair(rij, r2, true, h2), volume);
        };
        forEachListedNeighbor(lists, i, xi, [&](std::uint32_t j) {
          add(separation(periodic, seam, xi, xyz(readOnly(position + j))),
              mass * unpackPressureState(readOnly(state + j)).inverseDensity);
        });
        forEachWallNeighbor(walls, xi, [&](std::uint32_t b) {
          const Vec4 xb = readOnly(wall + b);
          add(xi - xyz(xb), xb.w);
        });
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
