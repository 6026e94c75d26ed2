// Stage (continuity density, the weakly compressible solver): the density advances by its rate
// of change at the positions and velocities the last step ended with, ρ_i += Δt Dρ_i/Dt, with
// δ-SPH's diffusion (core/continuity.hpp); then pressure from it. After the density pass, whose
// neighbour lists it walks. Taking the rate from the new velocities, as positions take them,
// is what keeps the scheme symplectic: from the old ones it is forward Euler on the sound
// waves, and a resting tank blew up within 0.02 s.
// Reads position, velocity, density, the lists and the walls; writes density, pressure and
// pressureState.
#pragma once

#include <cstdint>

#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbor_walk.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/continuity.hpp"

namespace sph::fluid {

// What the continuity pass reads of a neighbour: the state the pass started from, so that none
// reads a density this pass has already advanced.
struct ContinuityRecord {
  enum Field { kX, kY, kZ, kVX, kVY, kVZ, kDensity, kUnused };
};

template <class S, class V>
struct ContinuitySum {
  V vi;
  S rhoI;
  S rate{0.0f};  // Dρ_i/Dt
};

// Dρ_i/Dt from the fluid neighbours with δ-SPH's diffusion, and from the walls; then ρ_i, p_i.
template <class Kernels>
struct ContinuityPass {
  static constexpr bool kGradients = false;  // the diffusion reads the separation too
  static constexpr bool kSkipsCoincident = true;
  // The walls stand still, and no density diffuses into them; no objects take part (the
  // weakly compressible solver meets them by contact).
  static constexpr bool kWalls = true;
  static constexpr bool kObjects = false;
  static constexpr std::uint32_t kColumns = 7;
  Kernels kernels;
  FluidParameters p;
  float dt;
  float diffusion;  // δ h c0
  const Vec4* velocity;
  const float* density;
  float* next;
  float* pressure;
  Vec4* state;

  template <class S, class V>
  SPH_HD_INLINE ContinuitySum<S, V> start(std::size_t i) const {
    return ContinuitySum<S, V>{spread<V>(xyz(velocity[i])), S(density[i])};
  }
  template <class S, class V, class M, class C>
  SPH_HD_INLINE void addFluid(ContinuitySum<S, V>& sum, const Pair<S, V, M>& pair,
                              const C& columns) const {
    using R = ContinuityRecord;
    const V gradW = pairGradient(kernels, pair);
    const V vj{columns[R::kVX], columns[R::kVY], columns[R::kVZ]};
    sum.rate += densityRateTerm(S(p.mass), sum.vi - vj, gradW) +
                densityDiffusionTerm(S(diffusion), sum.rhoI, columns[R::kDensity], S(p.mass),
                                     pair.rij, pair.r2, gradW, spread<V>(p.gravity),
                                     S(p.restDensity), S(p.soundSpeed));
  }
  template <class S, class V, class M>
  SPH_HD_INLINE void addWall(ContinuitySum<S, V>& sum, const Pair<S, V, M>& pair, S volume) const {
    sum.rate += densityRateTerm(S(p.restDensity) * volume, sum.vi, pairGradient(kernels, pair));
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const ContinuitySum<S, V>& sum) const {
    const float rho = density[i] + dt * sumLanes(sum.rate);
    next[i] = rho;
    const PressureState s = pressureStateFromDensity(rho, p);
    pressure[i] = s.pressure;
    state[i] = packed(s);
  }
};

// `dt`: the step that took the particles from where the density was last advanced to where
// they are now (0 before the first step).
template <class B>
void integrateDensity(FluidParticles<B>& fluid, const Grid<B>& grid,
                      const BoundaryParticles<B>& boundary, const FluidParameters& params, float dt,
                      NeighborWalk walk) {
  using R = ContinuityRecord;
  const std::size_t n = fluid.count;
  fluid.scratchDensity.resize(n);
  fluid.batchRecords.resize(kRecordFields * (n + kBatchPadding));
  float* records = fluid.batchRecords.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const float* density = fluid.density.data();
  // The padding is far away, at rest, with a density to divide by.
  B::forEach(
      n + kBatchPadding, SPH_LAMBDA(std::size_t i) {
        const bool real = i < n;
        const Vec4 x = real ? position[i] : Vec4{1e30f, 1e30f, 1e30f, 0.0f};
        const Vec4 v = real ? velocity[i] : Vec4{0.0f, 0.0f, 0.0f, 0.0f};
        float* r = records + kRecordFields * i;
        r[R::kX] = x.x;
        r[R::kY] = x.y;
        r[R::kZ] = x.z;
        r[R::kVX] = v.x;
        r[R::kVY] = v.y;
        r[R::kVZ] = v.z;
        r[R::kDensity] = real ? density[i] : 1.0f;
        r[R::kUnused] = 0.0f;
      });
  const BoundaryParticles<B> noObjects{};
  withKernels(params, [&](auto kernels) {
    const ContinuityPass<decltype(kernels)> pass{
        kernels,
        params,
        dt,
        params.densityDiffusion * params.h * params.soundSpeed,
        velocity,
        density,
        fluid.scratchDensity.data(),
        fluid.pressure.data(),
        fluid.pressureState.data()};
    runPass(fluid, grid, boundary, noObjects, records, kernels, params.periodic, walk, pass);
  });
  fluid.density.swap(fluid.scratchDensity);
}

}  // namespace sph::fluid
