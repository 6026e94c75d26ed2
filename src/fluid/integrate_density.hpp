// Stage (continuity density, the weakly compressible solver): the density advances by its rate
// of change at the positions and velocities the last step ended with, ρ_i += Δt Dρ_i/Dt, with
// δ-SPH's diffusion (core/continuity.hpp); then pressure from it. After the density pass, whose
// neighbour lists it walks. Taking the rate from the new velocities, as positions take them,
// is what keeps the scheme symplectic: from the old ones it is forward Euler on the sound
// waves, and a resting tank blew up within 0.02 s.
// Reads position, velocity, density, the lists and the walls; writes density, pressure,
// pressureState (and the CPU's batch copies of them).
#pragma once

#include "fluid/integrate_density_batched.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/continuity.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

namespace detail {

template <class B, class Kernels>
void integrateDensityPass(FluidParticles<B>& fluid, const Grid<B>& grid,
                          const BoundaryParticles<B>& boundary, const FluidParameters& params,
                          float dt, Kernels kernels) {
  const std::size_t n = fluid.count;
  fluid.scratchDensity.resize(n);
  const NeighborLists lists = neighborLists(fluid, grid);
  const WallCells walls = wallCells(boundary);
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const Vec4* wall = boundary.position.data();  // w: volume ψ_b
  const float* density = fluid.density.data();
  float* next = fluid.scratchDensity.data();
  float* pressure = fluid.pressure.data();
  Vec4* state = fluid.pressureState.data();
  // The CPU's batched force pass reads these copies; the GPU has none.
  const bool batches = fluid.batchDensity.size() != 0;
  float* batchPOverRho2 = batches ? fluid.batchPOverRho2.data() : nullptr;
  float* batchPressure = batches ? fluid.batchPressure.data() : nullptr;
  float* batchDensity = batches ? fluid.batchDensity.data() : nullptr;
  const FluidParameters p = params;
  const float h2 = p.h * p.h;
  const float diffusion = p.densityDiffusion * p.h * p.soundSpeed;  // δ h c0

  B::forEach(
      n, SPH_LAMBDA(std::size_t i) {
        const Vec3 xi = xyz(position[i]);
        const bool seam = nearSeam(p.periodic, xi);
        const Vec3 vi = xyz(velocity[i]);
        const float rhoI = density[i];
        float rate = 0.0f;
        forEachListedNeighbor(lists, i, xi, [&](std::uint32_t j) {
          const Vec3 rij = separation(p.periodic, seam, xi, xyz(readOnly(position + j)));
          const float r2 = lengthSquared(rij);
          if (r2 >= h2 || r2 <= 0.0f) return;
          const Vec3 gradW = rij * kernels.gradFactor(realSqrt(r2));
          rate += densityRateTerm(p.mass, vi - xyz(readOnly(velocity + j)), gradW) +
                  densityDiffusionTerm(diffusion, rhoI, readOnly(density + j), p.mass, rij, r2,
                                       gradW, p.gravity, p.restDensity, p.soundSpeed);
        });
        // The walls stand still, and no density diffuses into them.
        forEachWallNeighbor(walls, xi, [&](std::uint32_t b) {
          const Vec4 xb = readOnly(wall + b);
          const Vec3 rib = xi - xyz(xb);
          const float r2 = lengthSquared(rib);
          if (r2 >= h2 || r2 <= 0.0f) return;
          rate += densityRateTerm(p.restDensity * xb.w, vi, rib * kernels.gradFactor(realSqrt(r2)));
        });
        const float rho = rhoI + dt * rate;
        next[i] = rho;
        const PressureState s = pressureStateFromDensity(rho, p);
        pressure[i] = s.pressure;
        state[i] = packed(s);
        if (batches) {
          batchPOverRho2[i] = s.pOverRho2;
          batchPressure[i] = s.pressure;
          batchDensity[i] = s.density;
        }
      });
  fluid.density.swap(fluid.scratchDensity);
}

}  // namespace detail

// `dt`: the step that took the particles from where the density was last advanced to where
// they are now (0 before the first step).
template <class B>
void integrateDensity(FluidParticles<B>& fluid, const Grid<B>& grid,
                      const BoundaryParticles<B>& boundary, const FluidParameters& params, float dt,
                      [[maybe_unused]] NeighborWalk walk) {
  withKernels(params, [&](auto kernels) {
#if !defined(__CUDACC__)
    if constexpr (B::kBatches) {
      if (walk == NeighborWalk::Batched) {
        detail::integrateDensityBatched(fluid, grid, boundary, params, dt, kernels);
        return;
      }
    }
#endif
    detail::integrateDensityPass(fluid, grid, boundary, params, dt, kernels);
  });
}

}  // namespace sph::fluid
