// Stage: density with pressure in one pass (Meteer 2011, Algorithm 1). Reads position, the
// walls and the objects taking part as boundary particles (none: objects.count 0). Writes
// density (unless it is state: continuity), pressure, pressureState and the neighbour lists.
#pragma once

#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbor_walk.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"

namespace sph::fluid {

template <class S>
struct DensitySum {
  S fluid{0.0f};  // Σ_j W_ij, self included (Meteer 2011, eq. 4)
  S walls{0.0f};  // Σ_b ψ_b W_ib over the walls' and the objects' particles
};

// ρ_i from the kernel sums (densityFromSums), then p_i by the equation of state. With
// continuity the density is state: the sums only bound it (keptDensity).
template <class Kernels>
struct DensityPass {
  Kernels kernels;
  FluidParameters p;
  bool integrated;  // continuity density
  float* density;
  float* pressure;
  Vec4* state;

  template <class S>
  SPH_HD_INLINE DensitySum<S> start(std::size_t) const {
    return {};
  }
  template <class S, class M>
  SPH_HD_INLINE void addFluid(DensitySum<S>& sum, S r2, M near) const {
    sum.fluid += kernelWhere(kernels, r2, near);
  }
  template <class S, class M>
  SPH_HD_INLINE void addWall(DensitySum<S>& sum, S r2, M near, S volume) const {
    sum.walls += volume * kernelWhere(kernels, r2, near);
  }
  template <class S>
  SPH_HD_INLINE void finish(std::size_t i, const DensitySum<S>& sum) const {
    const float summed = densityFromSums(sumLanes(sum.fluid), sumLanes(sum.walls), p);
    const PressureState s =
        pressureStateFromDensity(integrated ? keptDensity(density[i], summed, p) : summed, p);
    density[i] = s.density;
    pressure[i] = s.pressure;
    state[i] = packed(s);
  }
};

template <class B>
void computeDensityAndPressure(FluidParticles<B>& fluid, const Grid<B>& grid,
                               const BoundaryParticles<B>& boundary,
                               const BoundaryParticles<B>& objects, const FluidParameters& params,
                               NeighborWalk walk) {
  withKernels(params, [&](auto kernels) {
    const DensityPass<decltype(kernels)> pass{kernels,
                                              params,
                                              fluid.densityIsState,
                                              fluid.density.data(),
                                              fluid.pressure.data(),
                                              fluid.pressureState.data()};
    searchAndList(fluid, grid, boundary, objects, params.h, params.periodic, walk, pass);
  });
}

}  // namespace sph::fluid
