// Stages of the incompressible solver (DFSPH, core/dfsph.hpp):
//   prepareSolver      after the density pass: the records at this step's positions
//   solve NoDivergence corrects velocity until it compresses nothing (at the step's start); its
//                      first pass also gives each particle's factor β_i for the step
//   solve RestDensity  after the other forces: corrects the predicted velocity v + Δt a until
//                      the density it leads to is ρ0, and writes the acceleration that gives it
// Each solve is Jacobi iterations of two passes, the error measured between them, warm-started
// from the last step's K. Reads and writes only the solver's arrays and those named.
#pragma once

#include <cmath>
#include <cstdint>

#include "fluid/coarse_correction.hpp"
#include "fluid/dfsph_passes.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbor_walk.hpp"

namespace sph::fluid {

// The listed pairs' gradients are kept for the step (neighbor_walk.hpp) while they take no more
// memory than this. Kept, the dam break's DFSPH ran 20 % faster at 13,500 particles (3.5 MB of
// them); at 67,626 (17 MB) 7 % slower, the passes' extra stream costing more than the square
// roots it saved.
constexpr std::size_t kKeptGradientBytes = std::size_t(8) << 20;

template <class B>
void prepareSolver(FluidParticles<B>& fluid) {
  const std::size_t n = fluid.count;
  const std::size_t records = kRecordFields * (n + kBatchPadding);
  fluid.velocityRecords.resize(records);
  fluid.stiffnessRecords.resize(records);
  fluid.solverFactor.resize(n);
  fluid.solverWallGradient.resize(n);
  fluid.solverTotal.resize(n);
  fluid.solverError.resize(n);
  fluid.solverSignedError.resize(n);
  const bool keep = n * fluid.neighborStride * sizeof(float) <= kKeptGradientBytes;
  fluid.pairGradient.resize(keep ? n * fluid.neighborStride : 0);
  if (fluid.warmStart.size() < n) {
    fluid.warmStart.resize(n);
    Vec4* warm = fluid.warmStart.data();
    B::forEach(
        n, SPH_LAMBDA(std::size_t i) {
          warm[i] = Vec4{0.0f, 0.0f, 0.0f, 0.0f};
        });
  }
  const Vec4* position = fluid.position.data();
  float* velocityRecords = fluid.velocityRecords.data();
  float* stiffnessRecords = fluid.stiffnessRecords.data();
  // The padding is far away, still and without pressure: it never passes a distance test.
  B::forEach(
      n + kBatchPadding, SPH_LAMBDA(std::size_t i) {
        const Vec3 x = i < n ? xyz(position[i]) : Vec3{1e30f, 1e30f, 1e30f};
        float* v = velocityRecords + kRecordFields * i;
        float* k = stiffnessRecords + kRecordFields * i;
        for (std::uint32_t c = 0; c < kRecordFields; ++c) v[c] = k[c] = 0.0f;
        v[SolverRecord::kX] = k[SolverRecord::kX] = x.x;
        v[SolverRecord::kY] = k[SolverRecord::kY] = x.y;
        v[SolverRecord::kZ] = k[SolverRecord::kZ] = x.z;
      });
}

namespace detail {

// A solve starts from half the K the last step's solve ended with, and only in the bulk (ρ_i ≥
// ρ0 at the step's start): all of it overshoots, and an overshoot is never taken back, as K
// never turns negative; it grew from step to step until a resting tank blew apart. Pushed
// where nothing compresses, a particle drives the flow apart as well: a resting tank 30
// particles deep blew apart without the test.
constexpr float kWarmStartShare = 0.5f;

// The velocities to correct into the records, and the density solve's warm start K.
template <class B>
void beginSolve(FluidParticles<B>& fluid, SolverTarget target, float dt, bool warmStart,
                float restDensity) {
  const Vec4* velocity = fluid.velocity.data();
  const Vec4* acceleration = fluid.acceleration.data();
  const Vec4* warm = fluid.warmStart.data();
  const float* density = fluid.density.data();
  float* velocityRecords = fluid.velocityRecords.data();
  float* stiffnessRecords = fluid.stiffnessRecords.data();
  float* total = fluid.solverTotal.data();
  const bool predict = target == SolverTarget::RestDensity;
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 v = predict ? xyz(velocity[i]) + xyz(acceleration[i]) * dt : xyz(velocity[i]);
        float* r = velocityRecords + kRecordFields * i;
        r[SolverRecord::kVX] = v.x;
        r[SolverRecord::kVY] = v.y;
        r[SolverRecord::kVZ] = v.z;
        const bool bulk = density[i] >= restDensity;
        const float k = !warmStart || !bulk || !predict ? 0.0f : kWarmStartShare * warm[i].x;
        stiffnessRecords[kRecordFields * i + SolverRecord::kK] = k;
        total[i] = 0.0f;
      });
}

// The corrected velocities out of the records: as the velocity itself (divergence), or as
// the acceleration that takes the velocity there over Δt (density), with the density solve's
// total K kept for the next step's warm start. The particles' pressure is what both solves
// applied over the step, p = (K + K_div Δt_div / Δt) ρ²: at rest the divergence solve carries
// what the density solve, stopping at its tolerance, left (a resting tank read 3-4 % below ρgh
// without it, 0-2.6 % with it).
template <class B>
void endSolve(FluidParticles<B>& fluid, SolverTarget target, float dt) {
  Vec4* velocity = fluid.velocity.data();
  Vec4* acceleration = fluid.acceleration.data();
  Vec4* warm = fluid.warmStart.data();
  float* pressure = fluid.pressure.data();
  const float* density = fluid.density.data();
  const float* velocityRecords = fluid.velocityRecords.data();
  const float* total = fluid.solverTotal.data();
  const bool predict = target == SolverTarget::RestDensity;
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const float* r = velocityRecords + kRecordFields * i;
        const Vec3 v{r[SolverRecord::kVX], r[SolverRecord::kVY], r[SolverRecord::kVZ]};
        if (predict) {
          acceleration[i] = makeVec4((v - xyz(velocity[i])) / dt, acceleration[i].w);
          warm[i].x = total[i];
          pressure[i] = (total[i] + warm[i].y / dt) * density[i] * density[i];
        } else {
          velocity[i] = makeVec4(v, velocity[i].w);
          warm[i].y = total[i] * dt;
        }
      });
}

// The last rate pass's errors, summed in fixed point (kErrorScale): their average and the
// largest, over a distributed run's every process (their ghosts left out: the owners count
// them).
struct ErrorSums {
  std::uint64_t sum = 0, count = 0, largest = 0;
};

template <class B>
ErrorSums errorSums(const FluidParticles<B>& fluid, SolverGhosts* ghosts) {
  const std::uint64_t* error = fluid.solverError.data();
  const std::uint32_t* id = fluid.id.data();
  ErrorSums s = B::reduce(
      fluid.count, ErrorSums{},
      SPH_LAMBDA(std::size_t i) {
        return isGhost(id[i]) ? ErrorSums{} : ErrorSums{error[i], 1, error[i]};
      },
      SPH_LAMBDA(const ErrorSums& a, const ErrorSums& b) {
        return ErrorSums{a.sum + b.sum, a.count + b.count,
                         a.largest > b.largest ? a.largest : b.largest};
      });
  if (ghosts) ghosts->reduce(s.sum, s.count, s.largest);
  return s;
}

inline float averageError(const ErrorSums& s) {
  return s.count ? float(double(s.sum) / kErrorScale / double(s.count)) : 0.0f;
}

// A distributed run: fields [first, first + fields) of each ghost's record as its owner's.
template <class B>
void refreshGhostRecords(typename B::template Buffer<float>& records, std::uint32_t first,
                         std::uint32_t fields, SolverGhosts& ghosts) {
  const std::vector<std::uint32_t>& sentRows = ghosts.sentRows();
  const std::vector<std::uint32_t>& ghostRows = ghosts.ghostRows();
  typename B::template Buffer<std::uint32_t> rows;
  typename B::template Buffer<float> values;
  float* r = records.data();
  std::vector<float> sent(sentRows.size() * fields);
  if (!sentRows.empty()) {
    B::upload(rows, sentRows.data(), sentRows.size());
    values.resize(sent.size());
    const std::uint32_t* row = rows.data();
    float* v = values.data();
    B::forEach(
        sentRows.size(), SPH_LAMBDA(std::size_t k) {
          for (std::uint32_t c = 0; c < fields; ++c)
            v[k * fields + c] = r[kRecordFields * row[k] + first + c];
        });
    B::download(values, sent.data(), sent.size());
  }
  const std::vector<float> arrived = ghosts.exchange(sent, fields);
  if (ghostRows.empty()) return;
  B::upload(rows, ghostRows.data(), ghostRows.size());
  B::upload(values, arrived.data(), arrived.size());
  const std::uint32_t* row = rows.data();
  const float* v = values.data();
  B::forEach(
      ghostRows.size(), SPH_LAMBDA(std::size_t k) {
        for (std::uint32_t c = 0; c < fields; ++c)
          r[kRecordFields * row[k] + first + c] = v[k * fields + c];
      });
}

template <class B, class Kernels>
SolverReport iterate(FluidParticles<B>& fluid, const Grid<B>& grid,
                     const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                     const FluidParameters& params, const SolverSettings& settings,
                     SolverTarget target, float dt, NeighborWalk walk, CoarsePressure& coarse,
                     Kernels kernels) {
  const RatePass rate{target,
                      params.mass,
                      params.restDensity,
                      dt,
                      settings.minNeighbours,
                      fluid.velocityRecords.data(),
                      fluid.density.data(),
                      fluid.solverFactor.data(),
                      fluid.neighborCount.data(),
                      fluid.solverWallGradient.data(),
                      fluid.stiffnessRecords.data(),
                      fluid.solverError.data(),
                      fluid.solverSignedError.data()};
  const VelocityPass correct{params.mass,
                             params.restDensity,
                             dt,
                             fluid.solverWallGradient.data(),
                             fluid.stiffnessRecords.data(),
                             fluid.velocityRecords.data(),
                             fluid.solverTotal.data()};
  const float* velocityRecords = fluid.velocityRecords.data();
  const float* stiffnessRecords = fluid.stiffnessRecords.data();
  float* gradients = fluid.pairGradient.size() != 0 ? fluid.pairGradient.data() : nullptr;
  // Across processes, after each pass: the ghosts' velocities (the passes skip ghosts, and a
  // ghost's predicted velocity reads an acceleration its owner computed) or their K.
  SolverGhosts* ghosts = settings.ghosts;
  const auto shareVelocities = [&] {
    if (ghosts) refreshGhostRecords<B>(fluid.velocityRecords, SolverRecord::kVX, 3, *ghosts);
  };
  const auto shareStiffness = [&] {
    if (ghosts) refreshGhostRecords<B>(fluid.stiffnessRecords, SolverRecord::kK, 1, *ghosts);
  };
  shareVelocities();
  // Only the density solve starts warm: the divergence solve comes first in a step, and its
  // first pass finds the step's factors and wall gradients that a warm start would need.
  if (settings.warmStart && target == SolverTarget::RestDensity) {
    runPass(fluid, grid, boundary, objects, stiffnessRecords, kernels, params.periodic, walk,
            correct, gradients);
    shareVelocities();
  }
  SolverReport report;
  for (;;) {
    if (report.iterations == 0 && target == SolverTarget::NoDivergence) {
      const FactorAndRatePass first{
          {params.mass / params.restDensity, dfsphSmallestFactorSum(params.h),
           fluid.solverFactor.data(), fluid.solverWallGradient.data()},
          rate};
      runPass(fluid, grid, boundary, objects, velocityRecords, kernels, params.periodic, walk,
              first, gradients);
    } else {
      runPass(fluid, grid, boundary, objects, velocityRecords, kernels, params.periodic, walk, rate,
              gradients);
    }
    shareStiffness();
    const ErrorSums errors = errorSums(fluid, ghosts);
    report.averageError = averageError(errors);
    const bool done =
        report.iterations >= settings.minIterations && report.averageError <= settings.tolerance;
    if (done || report.iterations >= settings.maxIterations) {
      report.converged = done;
      report.largestError = float(double(errors.largest) / kErrorScale);
      return report;
    }
    // The smooth part of the error, at once (coarse_pressure.hpp): where Jacobi alone took 10.5
    // iterations a step in the dam break, with it 7.3; 21.7 and 11.6 at 67,626 particles.
    if (report.iterations == 0 && target == SolverTarget::RestDensity &&
        settings.coarseShare > 0.0f && !ghosts)
      addCoarseCorrection(fluid, grid, boundary, params, dt, settings.coarseShare, coarse);
    runPass(fluid, grid, boundary, objects, stiffnessRecords, kernels, params.periodic, walk,
            correct, gradients);
    shareVelocities();
    ++report.iterations;
  }
}

}  // namespace detail

// One solve (see above); `dt` is the step the error is predicted over; `coarse`: the density
// solve's coarse level, kept from solve to solve.
template <class B>
SolverReport solve(FluidParticles<B>& fluid, const Grid<B>& grid,
                   const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                   const FluidParameters& params, const SolverSettings& settings,
                   SolverTarget target, float dt, NeighborWalk walk, CoarsePressure& coarse) {
  SolverReport report;
  // A distributed run's process with no particles still takes part in every exchange.
  if (fluid.count == 0 && !settings.ghosts) return report;
  detail::beginSolve(fluid, target, dt, settings.warmStart, params.restDensity);
  withKernels(params, [&](auto kernels) {
    report = detail::iterate(fluid, grid, boundary, objects, params, settings, target, dt, walk,
                             coarse, kernels);
  });
  detail::endSolve(fluid, target, dt);
  return report;
}

}  // namespace sph::fluid
