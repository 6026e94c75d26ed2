// The passes of the position solver (core/pbf.hpp), each written once for one neighbour at a
// time and for a SIMD batch (neighbor_walk.hpp): the multipliers λ from the positions being
// corrected, the displacement the multipliers give, and XSPH's smoothing of the velocities.
// The two solver passes alternate between two record arrays, so that no pass writes what
// another particle of the same pass reads.
#pragma once

#include <cstdint>

#include "fluid/dfsph_passes.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/pbf.hpp"

namespace sph::fluid {

// The fields of the position solver's 8-float records.
struct PbfRecord {
  enum Field { kX, kY, kZ, kLambda };
  // XSPH's records
  enum VelocityField { kVX = 3, kVY, kVZ };
};

template <class S, class V>
struct MultiplierSum {
  S kernel{0.0f};                         // Σ_j W_ij, fluid neighbours
  S walls{0.0f};                          // Σ_b ψ_b W_ib
  V gradient{S(0.0f), S(0.0f), S(0.0f)};  // Σ V_j ∇W_ij, walls included
  V wall{S(0.0f), S(0.0f), S(0.0f)};      // Σ ψ_b ∇W_ib
  S squares{0.0f};                        // Σ |V_j ∇W_ij|², fluid only
};

// λ_i from the positions of `positions` (x, y, z): written with particle i's position into
// `multipliers`, which the displacement pass reads. Keeps G_w for it, and ρ_i/ρ0 - 1 ≥ 0 as
// the iteration's error.
template <class Kernels>
struct MultiplierPass {
  static constexpr bool kGradients = false;
  static constexpr bool kSkipsCoincident = false;
  static constexpr bool kWalls = true;
  static constexpr bool kObjects = true;
  static constexpr std::uint32_t kColumns = 3;
  Kernels kernels;
  float mass, restDensity, volume, relaxation;
  float selfKernel;  // W(0): the particle's own share of its density
  const float* positions;
  float* multipliers;
  Vec4* wallGradient;
  std::uint64_t* error;  // fixed point, kErrorScale

  template <class S, class V>
  SPH_HD_INLINE MultiplierSum<S, V> start(std::size_t) const {
    return {};
  }
  template <class S, class V, class M, class C>
  SPH_HD_INLINE void addFluid(MultiplierSum<S, V>& sum, const Pair<S, V, M>& pair, const C&) const {
    sum.kernel += pair.where(kernels.W(pair.r2));
    const V g = pairGradient(kernels, pair) * S(volume);
    sum.gradient += g;
    sum.squares += dot(g, g);
  }
  template <class S, class V, class M>
  SPH_HD_INLINE void addWall(MultiplierSum<S, V>& sum, const Pair<S, V, M>& pair, S volumeB) const {
    sum.walls += volumeB * pair.where(kernels.W(pair.r2));
    const V g = pairGradient(kernels, pair) * volumeB;
    sum.gradient += g;
    sum.wall += g;
  }
  template <class S, class V, class M>
  SPH_HD_INLINE void addMovingWall(MultiplierSum<S, V>& sum, const Pair<S, V, M>& pair, S volumeB,
                                   const V&) const {
    addWall(sum, pair, volumeB);
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const MultiplierSum<S, V>& sum) const {
    const float density =
        mass * (selfKernel + sumLanes(sum.kernel)) + restDensity * sumLanes(sum.walls);
    const Vec3 wall = sumLanes(sum.wall);
    const float lambda = pbfMultiplier(
        density, restDensity,
        pbfGradientSquares(sumLanes(sum.gradient), wall, sumLanes(sum.squares)), relaxation);
    const float* from = positions + kRecordFields * i;
    float* to = multipliers + kRecordFields * i;
    to[PbfRecord::kX] = from[PbfRecord::kX];
    to[PbfRecord::kY] = from[PbfRecord::kY];
    to[PbfRecord::kZ] = from[PbfRecord::kZ];
    to[PbfRecord::kLambda] = lambda;
    wallGradient[i] = makeVec4(wall);
    const float e = density / restDensity - 1.0f;
    const float counted = e > 0.0f ? (e < 16.0f ? e : 16.0f) : 0.0f;
    error[i] = static_cast<std::uint64_t>(double(counted) * kErrorScale);
  }
};

template <class S, class V>
struct DisplacementSum {
  S lambdaI;
  V dx{S(0.0f), S(0.0f), S(0.0f)};
};

// Δx_i from the multipliers (core/pbf.hpp), with Macklin & Müller's tensile correction:
// particle i's corrected position into `positions`, and λ_i added to the substep's total.
template <class Kernels>
struct DisplacementPass {
  static constexpr bool kGradients = false;
  static constexpr bool kSkipsCoincident = false;
  // The walls' share is 2 λ_i G_w, from the multiplier pass.
  static constexpr bool kWalls = false;
  static constexpr bool kObjects = false;
  static constexpr std::uint32_t kColumns = 4;  // x, y, z, λ
  Kernels kernels;
  float volume;
  float tensileStrength;     // k of s_corr
  float inverseTensileW;     // 1 / W(Δq)
  const float* multipliers;  // x, y, z, λ
  const Vec4* wallGradient;
  float* positions;
  float* total;

  template <class S, class V>
  SPH_HD_INLINE DisplacementSum<S, V> start(std::size_t i) const {
    return DisplacementSum<S, V>{S(multipliers[kRecordFields * i + PbfRecord::kLambda])};
  }
  template <class S, class V, class M, class C>
  SPH_HD_INLINE void addFluid(DisplacementSum<S, V>& sum, const Pair<S, V, M>& pair,
                              const C& columns) const {
    const S tensile =
        pbfTensileCorrection(S(tensileStrength), kernels.W(pair.r2) * S(inverseTensileW));
    sum.dx += pbfDisplacementTerm(S(volume), sum.lambdaI, columns[PbfRecord::kLambda], tensile,
                                  pairGradient(kernels, pair));
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const DisplacementSum<S, V>& sum) const {
    const float* from = multipliers + kRecordFields * i;
    const float lambda = from[PbfRecord::kLambda];
    const Vec3 dx = sumLanes(sum.dx) + pbfWallDisplacement(lambda, xyz(wallGradient[i]));
    float* to = positions + kRecordFields * i;
    to[PbfRecord::kX] = from[PbfRecord::kX] + dx.x;
    to[PbfRecord::kY] = from[PbfRecord::kY] + dx.y;
    to[PbfRecord::kZ] = from[PbfRecord::kZ] + dx.z;
    total[i] += lambda;
  }
};

template <class S, class V>
struct XsphSum {
  V vi;
  V dv{S(0.0f), S(0.0f), S(0.0f)};
};

// XSPH: each velocity moved towards its neighbours' by the coefficient c, into `velocity`.
template <class Kernels>
struct XsphPass {
  static constexpr bool kGradients = false;
  static constexpr bool kSkipsCoincident = false;
  static constexpr bool kWalls = false;
  static constexpr bool kObjects = false;
  static constexpr std::uint32_t kColumns = 6;  // x, y, z, v
  Kernels kernels;
  float coefficient, volume;
  const float* records;
  Vec4* velocity;

  SPH_HD_INLINE Vec3 velocityOf(std::size_t i) const {
    const float* r = records + kRecordFields * i;
    return Vec3{r[PbfRecord::kVX], r[PbfRecord::kVY], r[PbfRecord::kVZ]};
  }
  template <class S, class V>
  SPH_HD_INLINE XsphSum<S, V> start(std::size_t i) const {
    return XsphSum<S, V>{spread<V>(velocityOf(i))};
  }
  template <class S, class V, class M, class C>
  SPH_HD_INLINE void addFluid(XsphSum<S, V>& sum, const Pair<S, V, M>& pair,
                              const C& columns) const {
    const V vj{columns[PbfRecord::kVX], columns[PbfRecord::kVY], columns[PbfRecord::kVZ]};
    sum.dv += xsphTerm(S(coefficient), S(volume), vj - sum.vi, pair.where(kernels.W(pair.r2)));
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const XsphSum<S, V>& sum) const {
    velocity[i] = makeVec4(velocityOf(i) + sumLanes(sum.dv), velocity[i].w);
  }
};

}  // namespace sph::fluid
