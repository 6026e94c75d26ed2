// Stage (for force probes on walls, after the step's forces and solves, before the particles
// move): the fluid's force on each watched wall particle (the others get zero, at no cost), the
// exact opposite of what that particle did to the fluid this step — the wall pair terms of the
// force pass (pressure, unless the incompressible solver gives it, and friction) and, under DFSPH,
// the solves' mirrored pressure -2 m ρ0 ψ_b (p_i/ρ_i²) ∇W_ib (boundary_forces.hpp). Summed from the
// wall particle's side, without atomics, in the walls' cell order: the same for any thread count.
#pragma once

#include <cstddef>
#include <cstdint>

#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/eos.hpp"
#include "sph/core/momentum.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

namespace detail {

// A named template, not a generic lambda: nvcc's device lambdas may not sit inside one.
template <class B, class Options, class Kernels>
void wallForcesWith(const FluidParticles<B>& fluid, const Grid<B>& grid,
                    const BoundaryParticles<B>& walls, const FluidParameters& params,
                    const std::uint8_t* watched, Vec4* force, Kernels kernels) {
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const Vec4* state = fluid.pressureState.data();
  const float* pressure = fluid.pressure.data();
  const float* density = fluid.density.data();
  const Vec4* wall = walls.position.data();  // w: ψ_b
  const float h2 = params.h * params.h;
  const float mass = params.mass, restDensity = params.restDensity;
  const Periodicity periodic = params.periodic;
  const ForceConstants<float, Vec3, Kernels> constants(params, kernels);
  B::forEach(
      walls.count, SPH_LAMBDA(std::size_t b) {
        // Named here: nvcc's device lambdas may not first capture inside `if constexpr`.
        (void)pressure, (void)density, (void)restDensity, (void)kernels;
        if (!watched[b]) {
          force[b] = Vec4{0.0f, 0.0f, 0.0f, 0.0f};
          return;
        }
        const Vec4 xb = wall[b];
        const bool seam = nearSeam(periodic, xyz(xb));
        Vec3 sum{0.0f, 0.0f, 0.0f};  // Σ_i a_ib, the fluid's acceleration through b
        forEachNeighbor(spec, cellStart, xyz(xb), [&](std::uint32_t i) {
          const Vec3 rib = separation(periodic, seam, xyz(readOnly(position + i)), xyz(xb));
          const float r2 = lengthSquared(rib);
          if (r2 >= h2 || r2 <= 0.0f) return;
          const ForceTerms<float, Vec3, Options, Kernels> terms(
              constants, unpackPressureState(readOnly(state + i)), xyz(readOnly(velocity + i)));
          ForceSums<float, Vec3> pairSum;
          const auto pair = makePair(rib, r2, true, h2);
          terms.addWall(pairSum, pair, xb.w);
          sum += pairSum.acceleration;
          if constexpr (!Options::pressure) {
            const float ki =
                pressureOverDensitySquared(readOnly(pressure + i), readOnly(density + i));
            sum += pressureAccelerationSymmetric(restDensity * xb.w, ki, ki,
                                                 rib * kernels.gradFactor(pair.r));
          }
        });
        force[b] = makeVec4(sum * -mass, 0.0f);
      });
}

template <class B, ViscosityModel kViscosity, bool kPressure>
void wallForcesWithOptions(const FluidParticles<B>& fluid, const Grid<B>& grid,
                           const BoundaryParticles<B>& walls, const FluidParameters& params,
                           const std::uint8_t* watched, Vec4* force) {
  // The pressure form and surface tension do not enter a wall's pair terms.
  using Options = ForceOptions<PressureForm::Symmetric, kViscosity, false, kPressure>;
  withKernels(params, [&](auto kernels) {
    wallForcesWith<B, Options>(fluid, grid, walls, params, watched, force, kernels);
  });
}

template <class B, bool kPressure>
void wallForcesWithPressure(const FluidParticles<B>& fluid, const Grid<B>& grid,
                            const BoundaryParticles<B>& walls, const FluidParameters& params,
                            const std::uint8_t* watched, Vec4* force) {
  if (params.viscosityModel == ViscosityModel::Artificial) {
    wallForcesWithOptions<B, ViscosityModel::Artificial, kPressure>(fluid, grid, walls, params,
                                                                    watched, force);
  } else {
    wallForcesWithOptions<B, ViscosityModel::Muller, kPressure>(fluid, grid, walls, params, watched,
                                                                force);
  }
}

}  // namespace detail

// watched, force: one per wall particle, in the walls' order (B's memory); force xyz in N,
// w 0.
template <class B>
void wallForces(const FluidParticles<B>& fluid, const Grid<B>& grid,
                const BoundaryParticles<B>& walls, const FluidParameters& params,
                const std::uint8_t* watched, Vec4* force) {
  if (walls.count == 0) return;
  if (params.pressureForces) {
    detail::wallForcesWithPressure<B, true>(fluid, grid, walls, params, watched, force);
  } else {
    detail::wallForcesWithPressure<B, false>(fluid, grid, walls, params, watched, force);
  }
}

}  // namespace sph::fluid
