// Stage: density with pressure in one pass (Meteer 2011, Algorithm 1). Reads position, the
// walls and the objects taking part as boundary particles (none: objects.count 0). Writes
// density (unless it is state: continuity), pressure, pressureState and the neighbour lists.
#pragma once

#include "fluid/density_pressure_batched.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

namespace detail {

template <class B, class Kernels>
void densityPass(FluidParticles<B>& fluid, const Grid<B>& grid,
                 const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                 const FluidParameters& params, Kernels kernels) {
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const WallCells walls = wallCells(boundary);
  const WallCells objectCells = wallCells(objects);
  const Vec4* position = fluid.position.data();
  const Vec4* wall = boundary.position.data();
  const Vec4* object = objects.position.data();
  float* density = fluid.density.data();
  float* pressure = fluid.pressure.data();
  Vec4* state = fluid.pressureState.data();
  const std::uint32_t stride = fluid.neighborStride;
  std::uint32_t* neighbors = fluid.neighbors.data();
  std::uint32_t* neighborCount = fluid.neighborCount.data();
  const float h2 = params.h * params.h;
  const FluidParameters p = params;
  const bool integrated = fluid.densityIsState;

  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 xi = xyz(position[i]);
        const bool seam = nearSeam(p.periodic, xi);
        float sum = 0.0f, wallSum = 0.0f;  // Meteer 2011, eq. 4, self included; walls' volumes
        std::uint32_t* list = neighbors + i * stride;
        std::uint32_t count = 0;
        forEachNeighbor(spec, cellStart, xi, [&](std::uint32_t j) {
          const float r2 =
              lengthSquared(separation(p.periodic, seam, xi, xyz(readOnly(position + j))));
          if (r2 >= h2) return;
          sum += kernels.W(r2);
          if (j != i && count < stride) list[count] = j;
          if (j != i) ++count;
        });
        neighborCount[i] = count <= stride ? count : kNeighborOverflow;
        forEachWallNeighbor(walls, xi, [&](std::uint32_t b) {
          const Vec4 xb = readOnly(wall + b);
          wallSum += xb.w * kernels.W(lengthSquared(xi - xyz(xb)));
        });
        forEachWallNeighbor(objectCells, xi, [&](std::uint32_t k) {
          const Vec4 xk = readOnly(object + k);
          wallSum += xk.w * kernels.W(lengthSquared(xi - xyz(xk)));
        });
        // Continuity keeps the density integrate gave; the sums still list the neighbours.
        const PressureState s = pressureStateFromDensity(
            integrated ? keptDensity(density[i], densityFromSums(sum, wallSum, p), p)
                       : densityFromSums(sum, wallSum, p),
            p);
        density[i] = s.density;
        pressure[i] = s.pressure;
        state[i] = packed(s);
      });
}

}  // namespace detail

template <class B>
void computeDensityAndPressure(FluidParticles<B>& fluid, const Grid<B>& grid,
                               const BoundaryParticles<B>& boundary,
                               const BoundaryParticles<B>& objects, const FluidParameters& params,
                               [[maybe_unused]] NeighborWalk walk) {
  withKernels(params, [&](auto kernels) {
#if !defined(__CUDACC__)
    if constexpr (B::kBatches) {
      if (walk == NeighborWalk::Batched) {
        detail::densityPassBatched(fluid, grid, boundary, objects, params, kernels);
        return;
      }
    }
#endif
    detail::densityPass<B>(fluid, grid, boundary, objects, params, kernels);
  });
}

}  // namespace sph::fluid
