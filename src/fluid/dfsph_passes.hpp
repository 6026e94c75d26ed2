// The three passes of the incompressible solver (core/dfsph.hpp), each written once for one
// neighbour at a time and for a SIMD batch (solver_walk.hpp): the factor β_i, the predicted
// density error with the K_i that undoes it, and the velocity correction K gives.
#pragma once

#include <cstdint>

#include "fluid/dfsph_settings.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/dfsph.hpp"
#include "sph/core/momentum.hpp"

namespace sph::fluid {

// The fields of the solver's 8-float records.
struct SolverRecord {
  enum Field { kX, kY, kZ, kVX, kVY, kVZ };  // velocityRecords
  static constexpr int kK = 3;               // stiffnessRecords: x, y, z, K
};

// The fixed-point scale of the per-particle errors: an integer sum is the same on any thread
// count, so the iterations a solve takes, and with them the result, are too.
constexpr double kErrorScale = 4294967296.0;  // 2³²

template <class S, class V>
struct FactorSum {
  V gradient{S(0.0f), S(0.0f), S(0.0f)};  // Σ V_j ∇W_ij, walls included
  V wall{S(0.0f), S(0.0f), S(0.0f)};      // Σ ψ_b ∇W_ib
  S squares{0.0f};                        // Σ |V_j ∇W_ij|², fluid only
};

// β_i (core/dfsph.hpp), into solverFactor.
template <class Kernels>
struct FactorPass {
  Kernels kernels;
  float volume;    // of a fluid particle, m/ρ0
  float smallest;  // dfsphSmallestFactorSum
  float* factor;

  template <class S, class V>
  SPH_HD_INLINE FactorSum<S, V> start(std::size_t) const {
    return {};
  }
  template <class S, class V, class M, class C>
  SPH_HD_INLINE void addFluid(FactorSum<S, V>& sum, const Pair<S, V, M>& pair, const C&) const {
    const V g = pair.rij * (S(volume) * pair.where(kernels.gradFactor(pair.r)));
    sum.gradient += g;
    sum.squares += dot(g, g);
  }
  template <class S, class V, class M>
  SPH_HD_INLINE void addWall(FactorSum<S, V>& sum, const Pair<S, V, M>& pair, S volumeB) const {
    const V g = pair.rij * (volumeB * pair.where(kernels.gradFactor(pair.r)));
    sum.gradient += g;
    sum.wall += g;
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const FactorSum<S, V>& sum) const {
    factor[i] =
        dfsphFactor(sumLanes(sum.gradient), sumLanes(sum.wall), sumLanes(sum.squares), smallest);
  }
};

template <class S, class V>
struct RateSum {
  V vi;
  S rate{0.0f};  // Dρ_i/Dt
};

// From the velocities being corrected, each particle's predicted density error e_i ≥ 0 (a
// particle is never pulled towards its neighbours: the free surface reads low) and the K_i that
// would undo it alone (one Jacobi step, Bender & Koschier 2017). As the warm start's test it
// instead keeps the K_i it finds in the records where the particle is compressing, and zeroes
// it elsewhere: pushed where nothing compresses, a particle drives the flow apart, which no
// K ≥ 0 takes back (without the test a resting tank 30 particles deep blew apart).
template <class Kernels>
struct RatePass {
  Kernels kernels;
  SolverTarget target;
  float mass, restDensity, dt;
  std::uint32_t minNeighbours;  // SolverSettings
  const float* velocityRecords;
  const float* density;
  const float* factor;
  const std::uint32_t* neighborCount;
  bool warmStartTest;
  float* stiffnessRecords;
  std::uint64_t* error;

  template <class S, class V>
  SPH_HD_INLINE RateSum<S, V> start(std::size_t i) const {
    const float* r = velocityRecords + kRecordFields * i;
    return RateSum<S, V>{
        spread<V>(Vec3{r[SolverRecord::kVX], r[SolverRecord::kVY], r[SolverRecord::kVZ]})};
  }
  template <class S, class V, class M, class C>
  SPH_HD_INLINE void addFluid(RateSum<S, V>& sum, const Pair<S, V, M>& pair,
                              const C& columns) const {
    const V vj{columns[SolverRecord::kVX], columns[SolverRecord::kVY], columns[SolverRecord::kVZ]};
    const V gradW = pair.rij * pair.where(kernels.gradFactor(pair.r));
    sum.rate += densityRateTerm(S(mass), sum.vi - vj, gradW);
  }
  template <class S, class V, class M>
  SPH_HD_INLINE void addWall(RateSum<S, V>& sum, const Pair<S, V, M>& pair, S volumeB) const {
    const V gradW = pair.rij * pair.where(kernels.gradFactor(pair.r));
    sum.rate += densityRateTerm(S(restDensity) * volumeB, sum.vi, gradW);
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const RateSum<S, V>& sum) const {
    const float rate = sumLanes(sum.rate);
    const float e = target == SolverTarget::RestDensity
                        ? (density[i] + dt * rate) / restDensity - 1.0f
                        : (neighborCount[i] >= minNeighbours ? dt * rate / restDensity : 0.0f);
    const float counted = e > 0.0f ? e : 0.0f;
    float& k = stiffnessRecords[kRecordFields * i + SolverRecord::kK];
    k = warmStartTest ? (counted > 0.0f ? k : 0.0f)
                      : dfsphStiffness(counted, factor[i], restDensity, dt);
    const float clamped = counted < 1024.0f ? counted : 1024.0f;  // the fixed point's range
    error[i] = static_cast<std::uint64_t>(double(clamped) * kErrorScale);
  }
};

template <class S, class V>
struct VelocitySum {
  S ki;
  V dv{S(0.0f), S(0.0f), S(0.0f)};  // the acceleration the K's give
};

// The velocity correction of the K's just computed: Δv_i = Δt Σ_j -m_j (K_i + K_j) ∇W_ij, a
// wall particle mirroring K_i. Adds K_i to the solve's total.
template <class Kernels>
struct VelocityPass {
  Kernels kernels;
  float mass, restDensity, dt;
  const float* stiffnessRecords;
  float* velocityRecords;
  float* total;
  template <class S, class V>
  SPH_HD_INLINE VelocitySum<S, V> start(std::size_t i) const {
    return VelocitySum<S, V>{S(stiffnessRecords[kRecordFields * i + SolverRecord::kK])};
  }
  template <class S, class V, class M, class C>
  SPH_HD_INLINE void addFluid(VelocitySum<S, V>& sum, const Pair<S, V, M>& pair,
                              const C& columns) const {
    const V gradW = pair.rij * pair.where(kernels.gradFactor(pair.r));
    sum.dv += pressureAccelerationSymmetric(S(mass), sum.ki, columns[SolverRecord::kK], gradW);
  }
  template <class S, class V, class M>
  SPH_HD_INLINE void addWall(VelocitySum<S, V>& sum, const Pair<S, V, M>& pair, S volumeB) const {
    const V gradW = pair.rij * pair.where(kernels.gradFactor(pair.r));
    sum.dv += pressureAccelerationSymmetric(S(restDensity) * volumeB, sum.ki, sum.ki, gradW);
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const VelocitySum<S, V>& sum) const {
    const Vec3 dv = sumLanes(sum.dv) * dt;
    float* r = velocityRecords + kRecordFields * i;
    r[SolverRecord::kVX] += dv.x;
    r[SolverRecord::kVY] += dv.y;
    r[SolverRecord::kVZ] += dv.z;
    total[i] += stiffnessRecords[kRecordFields * i + SolverRecord::kK];
  }
};

}  // namespace sph::fluid
