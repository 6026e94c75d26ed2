// Stages of the position solver (Position Based Fluids, core/pbf.hpp), after the density pass
// at the predicted positions x* (which lists the neighbours for the substep):
//   solvePositions    Jacobi iterations of two passes, the multipliers and the displacement
//                     they give, on the positions in the solver's records; then the velocity
//                     v += (x - x*)/Δt that the corrections imply, the positions, and the
//                     pressure the multipliers stand for. The density is the last multiplier
//                     pass's, before its correction.
//   smoothVelocities  XSPH over the listed neighbours.
#pragma once

#include <cstdint>

#include "fluid/dfsph_settings.hpp"
#include "fluid/dfsph_solve.hpp"
#include "fluid/integrate.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbor_walk.hpp"
#include "fluid/pbf_passes.hpp"
#include "fluid/pbf_settings.hpp"

namespace sph::fluid {

namespace detail {

// Both record arrays start at x*, the padding far away.
template <class B>
void beginPositionSolve(FluidParticles<B>& fluid) {
  const std::size_t n = fluid.count;
  const std::size_t records = kRecordFields * (n + kBatchPadding);
  fluid.velocityRecords.resize(records);
  fluid.stiffnessRecords.resize(records);
  fluid.solverWallGradient.resize(n);
  fluid.solverTotal.resize(n);
  fluid.solverError.resize(n);
  const Vec4* position = fluid.position.data();
  float* a = fluid.velocityRecords.data();
  float* b = fluid.stiffnessRecords.data();
  float* total = fluid.solverTotal.data();
  B::forEach(
      n + kBatchPadding, SPH_LAMBDA(std::size_t i) {
        const Vec3 x = i < n ? xyz(position[i]) : Vec3{1e30f, 1e30f, 1e30f};
        float* ra = a + kRecordFields * i;
        float* rb = b + kRecordFields * i;
        for (std::uint32_t c = 0; c < kRecordFields; ++c) ra[c] = rb[c] = 0.0f;
        ra[PbfRecord::kX] = rb[PbfRecord::kX] = x.x;
        ra[PbfRecord::kY] = rb[PbfRecord::kY] = x.y;
        ra[PbfRecord::kZ] = rb[PbfRecord::kZ] = x.z;
        if (i < n) total[i] = 0.0f;
      });
}

// The corrected positions out of the records: the velocity their move implies, limited to
// maxSpeed, the position wrapped and kept in the domain as integration keeps it, the pressure.
// Returns how many speeds were limited.
template <class B>
std::size_t endPositionSolve(FluidParticles<B>& fluid, float dt, float restDensity, float maxSpeed,
                             const DomainParameters& domain) {
  Vec4* position = fluid.position.data();
  Vec4* velocity = fluid.velocity.data();
  float* pressure = fluid.pressure.data();
  const float* records = fluid.velocityRecords.data();
  const float* total = fluid.solverTotal.data();
  // Free once the density is kept: 1 where the guard limited the speed.
  std::uint64_t* limited = fluid.solverError.data();
  const DomainParameters d = domain;
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const float* r = records + kRecordFields * i;
        const Vec3 corrected{r[PbfRecord::kX], r[PbfRecord::kY], r[PbfRecord::kZ]};
        Vec3 v = xyz(velocity[i]) + (corrected - xyz(position[i])) / dt;
        const float speed2 = lengthSquared(v);
        limited[i] = speed2 > maxSpeed * maxSpeed ? 1u : 0u;
        if (limited[i] != 0u) v = v * (maxSpeed / realSqrt(speed2));
        Vec3 x = wrapIntoDomain(d.periodic, corrected);
        bool clamped = velocity[i].w != 0.0f;
        if (d.clampOutside && !d.dampedBox) {
          clamped = detail::clamp(x.x, v.x, d.min.x, d.max.x) || clamped;
          clamped = detail::clamp(x.y, v.y, d.min.y, d.max.y) || clamped;
          clamped = detail::clamp(x.z, v.z, d.min.z, d.max.z) || clamped;
        }
        velocity[i] = makeVec4(v, clamped ? 1.0f : 0.0f);
        position[i] = makeVec4(x);
        pressure[i] = pbfPressure(total[i], restDensity, dt);
      });
  return B::reduce(
      fluid.count, std::size_t{0}, SPH_LAMBDA(std::size_t i) { return std::size_t(limited[i]); },
      SPH_LAMBDA(std::size_t a, std::size_t b) { return a + b; });
}

// Lists the fluid particles within kObjectReach of each object particle at x*
// (FluidParticles::objectNeighbors), and zeroes objectPush.
template <class B>
void listObjectNeighbors(FluidParticles<B>& fluid, const Grid<B>& grid,
                         const BoundaryParticles<B>& objects, const FluidParameters& params) {
  const std::size_t n = objects.count;
  fluid.objectPush.resize(n);
  fluid.objectNeighbors.resize(n * kObjectNeighborStride);
  fluid.objectNeighborCount.resize(n);
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const Vec4* position = fluid.position.data();
  const Vec4* object = objects.position.data();
  Vec4* push = fluid.objectPush.data();
  std::uint32_t* list = fluid.objectNeighbors.data();
  std::uint32_t* listed = fluid.objectNeighborCount.data();
  const float reach = kObjectReach * params.h, reach2 = reach * reach;
  B::forEach(
      n, SPH_LAMBDA(std::size_t k) {
        const Vec3 xk = xyz(object[k]);
        std::uint32_t* mine = list + k * kObjectNeighborStride;
        std::uint32_t count = 0;
        forEachNeighborWithin(spec, cellStart, xk, reach, [&](std::uint32_t i) {
          if (lengthSquared(xyz(readOnly(position + i)) - xk) >= reach2) return;
          if (count < kObjectNeighborStride) mine[count] = i;
          ++count;
        });
        listed[k] = count <= kObjectNeighborStride ? count : kNeighborOverflow;
        push[k] = Vec4{0.0f, 0.0f, 0.0f, 0.0f};
      });
}

// What the last multiplier pass's λ (in `multipliers`, x, y, z, λ at that iteration's
// positions) moves the fluid by through each object particle k, gathered from k's side and
// added to objectPush: the fluid's share 2 λ_i ψ_k ∇W_ik (core/pbf.hpp) over the same pairs,
// evaluated as the multiplier pass evaluates them, so that the object takes the exact
// opposite of what the fluid got (to rounding in the sums' order). A named template, not a
// generic lambda: nvcc's device lambdas may not sit inside one.
template <class B, class Kernels>
void gatherObjectPush(FluidParticles<B>& fluid, const Grid<B>& grid,
                      const BoundaryParticles<B>& objects, const FluidParameters& params,
                      const float* multipliers, Kernels kernels) {
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const std::uint32_t* list = fluid.objectNeighbors.data();
  const std::uint32_t* listed = fluid.objectNeighborCount.data();
  const Vec4* object = objects.position.data();  // w: ψ_k
  Vec4* push = fluid.objectPush.data();
  const float h2 = params.h * params.h, reach = kObjectReach * params.h, mass = params.mass;
  B::forEach(
      objects.count, SPH_LAMBDA(std::size_t k) {
        const Vec4 xk = object[k];
        Vec3 sum{0.0f, 0.0f, 0.0f};
        const auto add = [&](std::uint32_t i) {
          const float* r = multipliers + kRecordFields * i;
          const Vec3 rik = Vec3{readOnly(r + PbfRecord::kX), readOnly(r + PbfRecord::kY),
                                readOnly(r + PbfRecord::kZ)} -
                           xyz(xk);
          const float r2 = lengthSquared(rik);
          if (r2 >= h2 || r2 <= 0.0f) return;
          const Vec3 g = pairGradient(kernels, makePair(rik, r2, true, h2)) * xk.w;
          sum += pbfWallDisplacement(readOnly(r + PbfRecord::kLambda), g);
        };
        const std::uint32_t count = listed[k];
        if (count != kNeighborOverflow) {
          const std::uint32_t* mine = list + k * kObjectNeighborStride;
          for (std::uint32_t m = 0; m < count; ++m) add(readOnly(mine + m));
        } else {
          forEachNeighborWithin(spec, cellStart, xyz(xk), reach, add);
        }
        push[k] = makeVec4(xyz(push[k]) + sum * mass);
      });
}

// The density each multiplier pass found, from its error: what frames and statistics read.
template <class B>
void keepSolvedDensity(FluidParticles<B>& fluid, float restDensity) {
  float* density = fluid.density.data();
  const std::uint64_t* error = fluid.solverError.data();
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        // Below ρ0 the error reads 0: the density pass's value stands.
        if (error[i] != 0)
          density[i] = restDensity * (1.0f + float(double(error[i]) / kErrorScale));
      });
}

}  // namespace detail

// One substep's solve over Δt (see above).
template <class B>
SolverReport solvePositions(FluidParticles<B>& fluid, const Grid<B>& grid,
                            const BoundaryParticles<B>& boundary,
                            const BoundaryParticles<B>& objects, const FluidParameters& params,
                            const PbfSettings& settings, float dt, const DomainParameters& domain,
                            NeighborWalk walk) {
  SolverReport report;
  detail::listObjectNeighbors(fluid, grid, objects, params);
  if (fluid.count == 0) return report;
  detail::beginPositionSolve(fluid);
  float* a = fluid.velocityRecords.data();   // x, y, z: the positions being corrected
  float* b = fluid.stiffnessRecords.data();  // x, y, z, λ
  withKernels(params, [&](auto kernels) {
    using Kernels = decltype(kernels);
    const float volume = params.mass / params.restDensity;
    const float wq = kernels.W(settings.tensileDistance * settings.tensileDistance);
    const MultiplierPass<Kernels> multipliers{kernels,
                                              params.mass,
                                              params.restDensity,
                                              volume,
                                              settings.relaxation,
                                              kernels.W(0.0f),
                                              a,
                                              b,
                                              fluid.solverWallGradient.data(),
                                              fluid.solverError.data()};
    const DisplacementPass<Kernels> displace{kernels,
                                             volume,
                                             settings.tensileStrength,
                                             wq > 0.0f ? 1.0f / wq : 0.0f,
                                             b,
                                             fluid.solverWallGradient.data(),
                                             a,
                                             fluid.solverTotal.data()};
    for (int k = 0; k < settings.iterations; ++k) {
      runPass(fluid, grid, boundary, objects, a, kernels, params.periodic, walk, multipliers);
      if (objects.count > 0) detail::gatherObjectPush(fluid, grid, objects, params, b, kernels);
      runPass(fluid, grid, boundary, objects, b, kernels, params.periodic, walk, displace);
    }
  });
  report.iterations = settings.iterations;
  if (settings.iterations > 0) {
    const detail::ErrorSums errors = detail::errorSums(fluid, nullptr);
    report.averageError = detail::averageError(errors);
    report.largestError = float(double(errors.largest) / kErrorScale);
  }
  report.converged = true;
  if (settings.iterations > 0) detail::keepSolvedDensity(fluid, params.restDensity);
  report.clamped =
      detail::endPositionSolve(fluid, dt, params.restDensity, settings.maxSpeed, domain);
  return report;
}

// XSPH (core/pbf.hpp) with coefficient c over the listed neighbours.
template <class B>
void smoothVelocities(FluidParticles<B>& fluid, const Grid<B>& grid,
                      const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                      const FluidParameters& params, float coefficient, NeighborWalk walk) {
  const std::size_t n = fluid.count;
  if (n == 0 || coefficient == 0.0f) return;
  fluid.batchRecords.resize(kRecordFields * (n + kBatchPadding));
  float* records = fluid.batchRecords.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  // The padding is far away, at rest.
  B::forEach(
      n + kBatchPadding, SPH_LAMBDA(std::size_t i) {
        const bool real = i < n;
        const Vec4 x = real ? position[i] : Vec4{1e30f, 1e30f, 1e30f, 0.0f};
        const Vec4 v = real ? velocity[i] : Vec4{0.0f, 0.0f, 0.0f, 0.0f};
        float* r = records + kRecordFields * i;
        r[PbfRecord::kX] = x.x;
        r[PbfRecord::kY] = x.y;
        r[PbfRecord::kZ] = x.z;
        r[PbfRecord::kVX] = v.x;
        r[PbfRecord::kVY] = v.y;
        r[PbfRecord::kVZ] = v.z;
        r[6] = r[7] = 0.0f;
      });
  withKernels(params, [&](auto kernels) {
    const XsphPass<decltype(kernels)> pass{kernels, coefficient, params.mass / params.restDensity,
                                           records, fluid.velocity.data()};
    runPass(fluid, grid, boundary, objects, records, kernels, params.periodic, walk, pass);
  });
}

}  // namespace sph::fluid
