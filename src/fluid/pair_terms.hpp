// What the passes add up over a particle's neighbours, written once for one neighbour at a
// time (S = float, V = Vec3: the GPU and the CPU's reference passes) and for a SIMD batch of
// neighbours (S = FloatBatch, V = BatchVec3: the CPU's batched passes). A pass differs from its
// twin only in how it walks the neighbours; what it sums for each is here, and the formulas it
// sums are in core (kernels.hpp, momentum.hpp, eos.hpp).
#pragma once

#include "fluid/parameters.hpp"
#include "sph/core/eos.hpp"
#include "sph/core/momentum.hpp"
#include "sph/core/select.hpp"

namespace sph::fluid {

// A neighbour, or a batch of them, seen from particle i. `near` says which are within reach:
// a bool that is true (a walker of one neighbour leaves the others out before), or a batch's
// mask. r2 and r are those of the pair where it is near and h², h elsewhere, so that no
// formula divides by the zero distance of a lane that is not a neighbour.
template <class S, class V, class M>
struct Pair {
  V rij;  // x_i - x_j
  S r2;
  S r;
  M near;

  // A kernel factor where the pair is near, zero elsewhere.
  SPH_HD_INLINE S where(S value) const { return select(near, value, S(0.0f)); }
};

template <class S, class V, class M>
SPH_HD_INLINE Pair<S, V, M> makePair(V rij, S r2, M near, float h2) {
  const S safeR2 = select(near, r2, S(h2));
  return {rij, safeR2, realSqrt(safeR2), near};
}

// What the other passes read of a particle after the density pass.
struct PressureState {
  float pOverRho2;       // p/ρ², the symmetric pressure form's factor
  float inverseDensity;  // 1/ρ
  float pressure;        // p
  float density;         // ρ
};

SPH_HD Vec4 packed(const PressureState& s) {
  return Vec4{s.pOverRho2, s.inverseDensity, s.pressure, s.density};
}
SPH_HD PressureState unpackPressureState(const Vec4& v) {
  return PressureState{v.x, v.y, v.z, v.w};
}

// Pressure from density; the density from the kernel sums over the fluid (Meteer 2011, eq. 4,
// the particle itself included) and over the walls, each wall particle counting with the mass
// ρ0 ψ_b of the fluid it stands for (Akinci et al. 2012, eq. 6).
SPH_HD PressureState pressureStateFromDensity(float rho, const FluidParameters& p) {
  const float pressure =
      pressureFromDensity(p.eos, rho, p.restDensity, p.stiffness, p.clampNegativePressure);
  return PressureState{pressureOverDensitySquared(pressure, rho), 1.0f / rho, pressure, rho};
}
// Continuity density's floor: the density it integrated, but never more than 1 % of ρ0 below
// what the kernel sums give. In the bulk the two agree (at rest within 0.01 %), and where the
// sums read low (the free surface) the integrated density stands; but a particle driven into
// a wall's particles has its sums rise at once, so the wall pushes it back. Integrated alone,
// a particle splashing against a closed tank's lid passed through it, its density falling
// below zero on the far side.
constexpr float kSummedDensityMargin = 0.01f;
SPH_HD float keptDensity(float integrated, float summed, const FluidParameters& p) {
  const float floor = summed - kSummedDensityMargin * p.restDensity;
  return integrated > floor ? integrated : floor;
}
SPH_HD float densityFromSums(float fluidKernelSum, float wallVolumeKernelSum,
                             const FluidParameters& p) {
  return p.mass * fluidKernelSum + p.restDensity * wallVolumeKernelSum;
}

// A kernel value where the pair is near, zero elsewhere: a term of the density's sums.
template <class S, class M, class Kernels>
SPH_HD_INLINE S kernelWhere(const Kernels& kernels, S r2, M near) {
  return kernels.W(select(near, r2, S(kernels.h2)));
}

// The colour field c (Meteer 2011, eqs. 11-12, with C_j = 1): a neighbour's share of its
// gradient, the surface normal, and of its Laplacian, the curvature surface tension needs.
// Walls count as filled space, so fluid against a wall is not free surface.
template <class S, class V, class M, class Kernels>
SPH_HD_INLINE V colourGradientTerm(const Kernels& kernels, const Pair<S, V, M>& pair, S volume) {
  return pair.rij * (volume * pair.where(kernels.colourGradFactor(pair.r)));
}
template <class S, class V, class M, class Kernels>
SPH_HD_INLINE S colourLaplacianTerm(const Kernels& kernels, const Pair<S, V, M>& pair, S volume) {
  return volume * pair.where(kernels.colourLaplacian(pair.r));
}

// The scene's choices for the force pass as compile-time constants, so the neighbour loop has
// no branch on them. Without `pressure` the pass leaves pressure to the incompressible solver.
template <PressureForm kForm, ViscosityModel kViscosity, bool kSurfaceTension,
          bool kPressure = true>
struct ForceOptions {
  static constexpr PressureForm form = kForm;
  static constexpr ViscosityModel viscosity = kViscosity;
  static constexpr bool surfaceTension = kSurfaceTension;
  static constexpr bool pressure = kPressure;
};

// What the force pass reads of a fluid neighbour for its pressure term: p/ρ² (symmetric form)
// or p (Meteer 2011, eq. 6).
template <class Options>
SPH_HD float pressureTerm(const PressureState& s) {
  return Options::form == PressureForm::Symmetric ? s.pOverRho2 : s.pressure;
}

// What the force pass adds up for particle i: kept apart from the per-particle constants
// (ForceTerms), small enough for the compiler to hold in registers through the loop.
template <class S, class V>
struct ForceSums {
  V acceleration{S(0.0f), S(0.0f), S(0.0f)};
  V colourGradient{S(0.0f), S(0.0f), S(0.0f)};
  S colourLaplacian{0.0f};
};

// The parameters every pair of the force pass reads, in every lane: made once per pass.
template <class S, class V, class Kernels>
struct ForceConstants {
  FluidParameters p;
  Kernels kernels;
  S mass, viscosity, soundSpeed, h, restDensity, wallFriction;
  V gravity;

  SPH_HD_INLINE ForceConstants(const FluidParameters& params, Kernels k)
      : p(params),
        kernels(k),
        mass(params.mass),
        viscosity(params.viscosity),
        soundSpeed(params.soundSpeed),
        h(params.h),
        restDensity(params.restDensity),
        wallFriction(params.wallFriction),
        gravity(spread<V>(params.gravity)) {}
};

// The viscous acceleration of fluid particle i (density ρ_i) from a boundary particle of mass
// m_b = ρ0 ψ_b whose velocity is v_i - vRel: the fluid's viscosity, with the boundary particle
// standing for fluid at rest density.
template <bool kArtificial, class S, class V, class M, class Kernels>
SPH_HD_INLINE V boundaryFriction(const ForceConstants<S, V, Kernels>& c, S densityI, S massB,
                                 const V& vRel, const Pair<S, V, M>& pair, const V& gradW) {
  if constexpr (kArtificial) {
    return artificialViscosityAcceleration(c.viscosity, c.soundSpeed, c.h, massB, densityI,
                                           c.restDensity, vRel, pair.rij, pair.r2, gradW);
  } else {
    return mullerViscosityAcceleration(c.viscosity, massB, densityI, c.restDensity, vRel,
                                       pair.where(c.kernels.laplacian(pair.r)));
  }
}

// The acceleration of particle i (Meteer 2011, Algorithm 2): pressure and viscosity from each
// fluid neighbour, the walls' pressure and friction (Akinci et al. 2012), surface tension.
template <class S, class V, class Options, class Kernels>
struct ForceTerms {
  static constexpr bool kSymmetric = Options::form == PressureForm::Symmetric;
  static constexpr bool kArtificial = Options::viscosity == ViscosityModel::Artificial;
  // 1/ρ_j only where a formula reads it: the paper's pressure form, surface tension.
  static constexpr bool kReadsInverseDensity = !kSymmetric || Options::surfaceTension;
  using Sums = ForceSums<S, V>;
  using Constants = ForceConstants<S, V, Kernels>;

  const Constants& c;
  float densityScalar;
  S pOverRho2I, pressureI, inverseDensityI, densityI;
  V vi;

  SPH_HD_INLINE ForceTerms(const Constants& constants, PressureState state, Vec3 velocity)
      : c(constants),
        densityScalar(state.density),
        pOverRho2I(state.pOverRho2),
        pressureI(state.pressure),
        inverseDensityI(state.inverseDensity),
        densityI(state.density),
        vi(spread<V>(velocity)) {}

  template <class M>
  SPH_HD_INLINE void addFluid(Sums& sums, const Pair<S, V, M>& pair, V vj, S pressureTermJ,
                              S densityJ) const {
    S inverseDensityJ(0.0f);
    if constexpr (kReadsInverseDensity) inverseDensityJ = S(1.0f) / densityJ;
    const V gradW = pair.rij * pair.where(c.kernels.gradFactor(pair.r));
    V& a = sums.acceleration;
    if constexpr (!Options::pressure) {
    } else if constexpr (kSymmetric) {
      a += pressureAccelerationSymmetric(c.mass, pOverRho2I, pressureTermJ, gradW);
    } else {
      a += pressureAccelerationPaper(c.mass, pressureI, inverseDensityI, pressureTermJ,
                                     inverseDensityJ, gradW);
    }
    const V vij = vi - vj;
    if constexpr (kArtificial) {
      a += artificialViscosityAcceleration(c.viscosity, c.soundSpeed, c.h, c.mass, densityI,
                                           densityJ, vij, pair.rij, pair.r2, gradW);
    } else {
      a += mullerViscosityAcceleration(c.viscosity, c.mass, densityI, densityJ, vij,
                                       pair.where(c.kernels.laplacian(pair.r)));
    }
    if constexpr (Options::surfaceTension) {
      const S volumeJ = c.mass * inverseDensityJ;
      sums.colourGradient += colourGradientTerm(c.kernels, pair, volumeJ);
      sums.colourLaplacian += colourLaplacianTerm(c.kernels, pair, volumeJ);
    }
  }

  // A wall particle of volume ψ_b: a mirror of the fluid at the pressure extrapolated to it,
  // with the walls' friction as a viscosity scaled by wall_friction.
  template <class M>
  SPH_HD_INLINE void addWall(Sums& sums, const Pair<S, V, M>& pair, S volumeB) const {
    const S massB = c.restDensity * volumeB;
    const V gradW = pair.rij * pair.where(c.kernels.gradFactor(pair.r));
    V& a = sums.acceleration;
    if constexpr (Options::pressure) {
      const S pB =
          wallPressure(pressureI, densityI, c.gravity, -pair.rij, c.p.clampNegativePressure);
      a += boundaryPressureAcceleration(massB, pressureI, densityI, pB, gradW);
    } else {
      // The incompressible solve mirrors the fluid's K into the walls (dfsph_passes.hpp); the
      // hydrostatic part of the wall's pressure, which no K carries, acts here.
      const S pB = wallPressure(S(0.0f), densityI, c.gravity, -pair.rij, true);
      a += boundaryPressureAcceleration(massB, S(0.0f), densityI, pB, gradW);
    }
    if (c.p.wallFriction > 0.0f)
      a += boundaryFriction<kArtificial>(c, densityI, massB, vi, pair, gradW) * c.wallFriction;
    if constexpr (Options::surfaceTension)
      sums.colourGradient += colourGradientTerm(c.kernels, pair, volumeB);
  }

  // An object's particle as a boundary particle of the incompressible solver (interaction
  // coupling "boundary"): the solve gives its pressure; here the fluid's own viscosity against
  // the particle's motion, which interaction/boundary_forces.hpp gives the object back.
  template <class M>
  SPH_HD_INLINE void addObject(Sums& sums, const Pair<S, V, M>& pair, S volumeB,
                               const V& velocityB) const {
    const V gradW = pair.rij * pair.where(c.kernels.gradFactor(pair.r));
    sums.acceleration += boundaryFriction<kArtificial>(c, densityI, c.restDensity * volumeB,
                                                       vi - velocityB, pair, gradW);
  }

  // The pair sums with gravity, the embedding application's acceleration and surface tension.
  SPH_HD_INLINE Vec3 total(const Sums& sums, Vec3 external) const {
    Vec3 a = c.p.gravity + external + sumLanes(sums.acceleration);
    if constexpr (Options::surfaceTension) {
      a += surfaceTensionAcceleration(c.p.surfaceTension, c.p.surfaceThreshold,
                                      sumLanes(sums.colourGradient), sumLanes(sums.colourLaplacian),
                                      densityScalar);
    }
    return a;
  }
};

}  // namespace sph::fluid
