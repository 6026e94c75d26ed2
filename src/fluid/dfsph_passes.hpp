// The three passes of the incompressible solver (core/dfsph.hpp), each written once for one
// neighbour at a time and for a SIMD batch (neighbor_walk.hpp): the factor β_i, the predicted
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

// The density, as a share of ρ0, that marks a full neighbourhood whatever its walls: a
// particle on the free surface reads well below it.
constexpr float kBulkDensity = 0.95f;

template <class S, class V>
struct FactorSum {
  V gradient{S(0.0f), S(0.0f), S(0.0f)};  // Σ V_j ∇W_ij, walls included
  V wall{S(0.0f), S(0.0f), S(0.0f)};      // Σ ψ_b ∇W_ib, the objects' particles included
  S squares{0.0f};                        // Σ |V_j ∇W_ij|², fluid only
  S boundaryFlow{0.0f};                   // Σ ψ_b v_b·∇W_ib: the objects' motion
};

// β_i (core/dfsph.hpp), into solverFactor.
struct FactorPass {
  static constexpr bool kGradients = true;
  static constexpr bool kFirstOfStep = true;
  static constexpr bool kSkipsCoincident = false;
  static constexpr bool kWalls = true;
  static constexpr bool kObjects = true;
  float volume;    // of a fluid particle, m/ρ0
  float smallest;  // dfsphSmallestFactorSum
  float* factor;
  // xyz: G_w = Σ_b ψ_b ∇W_ib, w: Σ_b ψ_b v_b·∇W_ib, for the passes after this one: the
  // boundary particles do not move within a step.
  Vec4* wallGradient;

  template <class S, class V>
  SPH_HD_INLINE FactorSum<S, V> start(std::size_t) const {
    return {};
  }
  template <class S, class V, class C>
  SPH_HD_INLINE void addFluid(FactorSum<S, V>& sum, const V& gradW, const C&) const {
    const V g = gradW * S(volume);
    sum.gradient += g;
    sum.squares += dot(g, g);
  }
  template <class S, class V>
  SPH_HD_INLINE void addWall(FactorSum<S, V>& sum, const V& gradW, S volumeB) const {
    const V g = gradW * volumeB;
    sum.gradient += g;
    sum.wall += g;
  }
  template <class S, class V>
  SPH_HD_INLINE void addMovingWall(FactorSum<S, V>& sum, const V& gradW, S volumeB,
                                   const V& velocityB) const {
    addWall(sum, gradW, volumeB);
    sum.boundaryFlow += volumeB * dot(velocityB, gradW);
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const FactorSum<S, V>& sum) const {
    const Vec3 wall = sumLanes(sum.wall);
    factor[i] = dfsphFactor(sumLanes(sum.gradient), wall, sumLanes(sum.squares), smallest);
    wallGradient[i] = makeVec4(wall, sumLanes(sum.boundaryFlow));
  }
};

template <class S, class V>
struct RateSum {
  V vi;
  S rate{0.0f};  // Dρ_i/Dt
};

// From the velocities being corrected, each particle's predicted density error e_i ≥ 0 (a
// particle is never pulled towards its neighbours: the free surface reads low) and the K_i that
// would undo it alone (one Jacobi step, Bender & Koschier 2017).
struct RatePass {
  static constexpr bool kGradients = true;
  static constexpr bool kFirstOfStep = false;
  static constexpr bool kSkipsCoincident = false;
  static constexpr std::uint32_t kColumns = 6;  // x, y, z, v
  // Boundary particles do not move within a step: their share is ρ0 (v_i·G_w - Σ ψ_b v_b·∇W_ib),
  // kept by the factor pass.
  static constexpr bool kWalls = false;
  static constexpr bool kObjects = false;
  SolverTarget target;
  float mass, restDensity, dt;
  std::uint32_t minNeighbours;  // SolverSettings
  const float* velocityRecords;
  const float* density;
  const float* factor;
  const std::uint32_t* neighborCount;
  const Vec4* wallGradient;
  float* stiffnessRecords;
  std::uint64_t* error;
  float* signedError;  // e_i before it is counted: what the coarse level averages

  // A particle the divergence solve corrects: one with a full neighbourhood, of fluid or of
  // fluid and walls (a particle against a wall has half the fluid neighbours, and its density).
  SPH_HD_INLINE bool inBulk(std::size_t i) const {
    return neighborCount[i] >= minNeighbours || density[i] >= kBulkDensity * restDensity;
  }
  SPH_HD_INLINE Vec3 velocityOf(std::size_t i) const {
    const float* r = velocityRecords + kRecordFields * i;
    return Vec3{r[SolverRecord::kVX], r[SolverRecord::kVY], r[SolverRecord::kVZ]};
  }
  template <class S, class V>
  SPH_HD_INLINE RateSum<S, V> start(std::size_t i) const {
    return RateSum<S, V>{spread<V>(velocityOf(i))};
  }
  template <class S, class V, class C>
  SPH_HD_INLINE void addFluid(RateSum<S, V>& sum, const V& gradW, const C& columns) const {
    const V vj{columns[SolverRecord::kVX], columns[SolverRecord::kVY], columns[SolverRecord::kVZ]};
    sum.rate += densityRateTerm(S(mass), sum.vi - vj, gradW);
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const RateSum<S, V>& sum) const {
    const Vec4 boundary = wallGradient[i];
    const float rate =
        sumLanes(sum.rate) + restDensity * (dot(velocityOf(i), xyz(boundary)) - boundary.w);
    const float e = target == SolverTarget::RestDensity
                        ? (density[i] + dt * rate) / restDensity - 1.0f
                        : (inBulk(i) ? dt * rate / restDensity : 0.0f);
    const float counted = e > 0.0f ? e : 0.0f;
    signedError[i] = e;
    stiffnessRecords[kRecordFields * i + SolverRecord::kK] =
        dfsphStiffness(counted, factor[i], restDensity, dt);
    // The fixed point's range: 16 × 2³² a particle leaves room in 64 bits for 2³⁸ particles.
    const float clamped = counted < 16.0f ? counted : 16.0f;
    error[i] = static_cast<std::uint64_t>(double(clamped) * kErrorScale);
  }
};

// The factor and the first rate pass of a step in one walk over the neighbours: the rate pass
// reads only particle i's own factor, which the factor pass has just summed.
struct FactorAndRatePass {
  static constexpr bool kGradients = true;
  static constexpr bool kFirstOfStep = true;
  static constexpr bool kSkipsCoincident = false;
  static constexpr std::uint32_t kColumns = RatePass::kColumns;
  static constexpr bool kWalls = true;
  static constexpr bool kObjects = true;
  FactorPass factor;
  RatePass rate;

  template <class S, class V>
  struct Sum {
    FactorSum<S, V> factor;
    RateSum<S, V> rate;
  };
  template <class S, class V>
  SPH_HD_INLINE Sum<S, V> start(std::size_t i) const {
    return {factor.template start<S, V>(i), rate.template start<S, V>(i)};
  }
  template <class S, class V, class C>
  SPH_HD_INLINE void addFluid(Sum<S, V>& sum, const V& gradW, const C& columns) const {
    factor.addFluid(sum.factor, gradW, columns);
    rate.addFluid(sum.rate, gradW, columns);
  }
  template <class S, class V>
  SPH_HD_INLINE void addWall(Sum<S, V>& sum, const V& gradW, S volumeB) const {
    factor.addWall(sum.factor, gradW, volumeB);
  }
  template <class S, class V>
  SPH_HD_INLINE void addMovingWall(Sum<S, V>& sum, const V& gradW, S volumeB,
                                   const V& velocityB) const {
    factor.addMovingWall(sum.factor, gradW, volumeB, velocityB);
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const Sum<S, V>& sum) const {
    factor.finish(i, sum.factor);
    rate.finish(i, sum.rate);
  }
};

template <class S, class V>
struct VelocitySum {
  S ki;
  V dv{S(0.0f), S(0.0f), S(0.0f)};  // the acceleration the K's give
};

// The velocity correction of the K's just computed: Δv_i = Δt Σ_j -m_j (K_i + K_j) ∇W_ij, a
// wall particle mirroring K_i. Adds K_i to the solve's total.
struct VelocityPass {
  static constexpr bool kGradients = true;
  static constexpr bool kFirstOfStep = false;
  static constexpr bool kSkipsCoincident = false;
  static constexpr std::uint32_t kColumns = 4;  // x, y, z, K
  // The walls mirror K_i: their share is -2 ρ0 K_i G_w, from the factor pass.
  static constexpr bool kWalls = false;
  static constexpr bool kObjects = false;
  float mass, restDensity, dt;
  const Vec4* wallGradient;
  const float* stiffnessRecords;
  float* velocityRecords;
  float* total;
  template <class S, class V>
  SPH_HD_INLINE VelocitySum<S, V> start(std::size_t i) const {
    return VelocitySum<S, V>{S(stiffnessRecords[kRecordFields * i + SolverRecord::kK])};
  }
  template <class S, class V, class C>
  SPH_HD_INLINE void addFluid(VelocitySum<S, V>& sum, const V& gradW, const C& columns) const {
    sum.dv += pressureAccelerationSymmetric(S(mass), sum.ki, columns[SolverRecord::kK], gradW);
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const VelocitySum<S, V>& sum) const {
    const float ki = stiffnessRecords[kRecordFields * i + SolverRecord::kK];
    const Vec3 walls = pressureAccelerationSymmetric(restDensity, ki, ki, xyz(wallGradient[i]));
    const Vec3 dv = (sumLanes(sum.dv) + walls) * dt;
    float* r = velocityRecords + kRecordFields * i;
    r[SolverRecord::kVX] += dv.x;
    r[SolverRecord::kVY] += dv.y;
    r[SolverRecord::kVZ] += dv.z;
    total[i] += stiffnessRecords[kRecordFields * i + SolverRecord::kK];
  }
};

}  // namespace sph::fluid
