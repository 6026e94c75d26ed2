// Stage (outside the step, for the probes): the fluid's sums at given points (core/probe.hpp)
// as a frame taken now would show it: the positions the step ended at, the densities and
// pressures it computed, found through the step's grid (particles move less than half a cell a
// step, as for the surface flags).
#pragma once

#include <cstddef>

#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/particles.hpp"
#include "sph/core/probe.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

namespace detail {

// A named template, not a generic lambda: nvcc's device lambdas may not sit inside one.
template <class B, class Kernels>
void samplePointsWith(const FluidParticles<B>& fluid, const Grid<B>& grid,
                      const FluidParameters& params, const Vec4* points, std::size_t count,
                      PointSums* out, Kernels kernels) {
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const float* density = fluid.density.data();
  const float* pressure = fluid.pressure.data();
  const float h2 = params.h * params.h;
  const float mass = params.mass;
  const Periodicity periodic = params.periodic;
  B::forEach(
      count, SPH_LAMBDA(std::size_t k) {
        const Vec3 x = xyz(points[k]);
        const bool seam = nearSeam(periodic, x);
        PointSums sums;
        forEachNeighbor(spec, cellStart, x, [&](std::uint32_t j) {
          const float r2 =
              lengthSquared(separation(periodic, seam, x, xyz(readOnly(position + j))));
          if (r2 >= h2) return;
          const float rho = readOnly(density + j);
          addToPointSums(sums, mass / rho * kernels.W(r2), readOnly(pressure + j), rho,
                         xyz(readOnly(velocity + j)));
        });
        out[k] = sums;
      });
}

}  // namespace detail

// points: xyz; out: one PointSums each (both in B's memory).
template <class B>
void samplePoints(const FluidParticles<B>& fluid, const Grid<B>& grid,
                  const FluidParameters& params, const Vec4* points, std::size_t count,
                  PointSums* out) {
  if (count == 0) return;
  withKernels(params, [&](auto kernels) {
    detail::samplePointsWith(fluid, grid, params, points, count, out, kernels);
  });
}

}  // namespace sph::fluid
