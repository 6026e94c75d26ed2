// The continuity pass (integrate_density.hpp) on the CPU, a SIMD batch of neighbours at a time:
// the same sums (core/continuity.hpp), the neighbours read from 8-float records of the state the
// pass started from, so that no lane reads a density this pass has already advanced.
#pragma once

#if !defined(__CUDACC__)

#include "fluid/batches.hpp"
#include "fluid/pair_terms.hpp"
#include "sph/core/continuity.hpp"

namespace sph::fluid::detail {

struct ContinuityRecord {
  enum Field { kX, kY, kZ, kVX, kVY, kVZ, kDensity, kUnused, kFields };
};

template <class Kernels>
void integrateDensityBatched(FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                             const BoundaryParticles<CpuBackend>& boundary,
                             const FluidParameters& params, float dt, Kernels kernels) {
  using R = ContinuityRecord;
  const std::size_t n = fluid.count;
  fluid.scratchDensity.resize(n);
  // The density pass has padded the positions: far away, never within reach.
  const float* x = fluid.batchX.data();
  const float* y = fluid.batchY.data();
  const float* z = fluid.batchZ.data();
  const Vec4* velocity = fluid.velocity.data();
  const float* density = fluid.density.data();
  fluid.batchRecords.resize(R::kFields * (n + kBatchPadding));
  float* records = fluid.batchRecords.data();
  CpuBackend::forEach(n + kBatchPadding, [=](std::size_t i) {
    const bool real = i < n;
    const Vec4 v = real ? velocity[i] : Vec4{0.0f, 0.0f, 0.0f, 0.0f};
    float* r = records + R::kFields * i;
    r[R::kX] = x[i];
    r[R::kY] = y[i];
    r[R::kZ] = z[i];
    r[R::kVX] = v.x;
    r[R::kVY] = v.y;
    r[R::kVZ] = v.z;
    r[R::kDensity] = real ? density[i] : 1.0f;  // a density to divide by
    r[R::kUnused] = 0.0f;
  });

  const NeighborLists lists = neighborLists(fluid, grid);
  const BoundaryBatches walls = boundaryBatches(boundary);
  float* next = fluid.scratchDensity.data();
  float* pressure = fluid.pressure.data();
  Vec4* state = fluid.pressureState.data();
  float* batchPOverRho2 = fluid.batchPOverRho2.data();
  float* batchPressure = fluid.batchPressure.data();
  float* batchDensity = fluid.batchDensity.data();
  const FluidParameters p = params;
  const float h2 = p.h * p.h;
  const FloatBatch h2Batch(h2), zero(0.0f), mass(p.mass), restDensity(p.restDensity),
      soundSpeed(p.soundSpeed), diffusion(p.densityDiffusion * p.h * p.soundSpeed);
  const BatchVec3 gravity = broadcast(p.gravity);

  CpuBackend::forEach(n, [=](std::size_t i) {
    const Vec3 xs{x[i], y[i], z[i]};
    const BatchVec3 xi = broadcast(xs);
    const bool seam = nearSeam(p.periodic, xs);
    const BatchVec3 vi = broadcast(xyz(velocity[i]));
    const float rhoScalar = density[i];
    const FloatBatch rhoI(rhoScalar);
    FloatBatch rate(0.0f);
    const auto addFluid = [&](const FloatBatch(&c)[R::kFields],
                              const FloatBatch::mask_type& candidates) SPH_BATCH_INLINE_LAMBDA {
      const BatchVec3 rij =
          separation(p.periodic, seam, xi, BatchVec3{c[R::kX], c[R::kY], c[R::kZ]});
      const FloatBatch r2 = dot(rij, rij);
      const auto near = candidates && r2 < h2Batch && r2 > zero;
      if (stdx::none_of(near)) return;
      const auto pair = makePair(rij, r2, near, h2);
      const BatchVec3 gradW = rij * pair.where(kernels.gradFactor(pair.r));
      const BatchVec3 vj{c[R::kVX], c[R::kVY], c[R::kVZ]};
      rate += densityRateTerm(mass, vi - vj, gradW) +
              densityDiffusionTerm(diffusion, rhoI, c[R::kDensity], mass, pair.rij, pair.r2, gradW,
                                   gravity, restDensity, soundSpeed);
    };
    forEachNeighborBatch(
        lists, i, xs,
        [&](const std::uint32_t* at) SPH_BATCH_INLINE_LAMBDA {
          FloatBatch c[R::kFields];
          gatherRecords(records, at, c);
          addFluid(c, FloatBatch::mask_type(true));
        },
        [&](std::uint32_t j, const FloatBatch::mask_type& candidates) {
          std::uint32_t at[kBatch];
          for (std::uint32_t k = 0; k < kBatch; ++k) at[k] = j + k;
          FloatBatch c[R::kFields];
          gatherRecords(records, at, c);
          addFluid(c, candidates);
        });
    // The walls stand still, and no density diffuses into them.
    forEachBoundaryPairBatch(
        walls, xs, xi, h2, [&](const auto& pair, FloatBatch volume, std::uint32_t) {
          const BatchVec3 gradW = pair.rij * pair.where(kernels.gradFactor(pair.r));
          rate += densityRateTerm(restDensity * volume, vi, gradW);
        });
    const float rho = rhoScalar + dt * sumLanes(rate);
    next[i] = rho;
    const PressureState s = pressureStateFromDensity(rho, p);
    pressure[i] = s.pressure;
    state[i] = packed(s);
    batchPOverRho2[i] = s.pOverRho2;
    batchPressure[i] = s.pressure;
    batchDensity[i] = s.density;
  });
  fluid.density.swap(fluid.scratchDensity);
}

}  // namespace sph::fluid::detail

#endif  // !__CUDACC__
