// Pairwise accelerations of the momentum equation. `gradW` is ∇_i W(x_i - x_j); `rij` is
// x_i - x_j, `vij` is v_i - v_j. Each pair term is antisymmetric when multiplied by the mass
// of i, so a sum over all pairs conserves linear momentum.
//
// Each is written once for a float and a Vec3 (the GPU, scalar CPU code) and for a batch of
// floats and a BatchVec3 (the CPU's SIMD passes): S is the scalar type, V the vector type.
#pragma once

#include "sph/core/select.hpp"
#include "sph/core/vec.hpp"

namespace sph {

// The per-particle factor of the symmetric form, p/ρ², computed once per particle.
SPH_HD float pressureOverDensitySquared(float pressure, float density) {
  return pressure / (density * density);
}

// The 2021 CUDA SPH tutorial's symmetric form: -m_j (p_i/ρ_i² + p_j/ρ_j²) ∇W, from the
// per-particle factors.
template <class S, class V>
SPH_HD V pressureAccelerationSymmetric(S massJ, S pOverRho2I, S pOverRho2J, V gradW) {
  return gradW * (-massJ * (pOverRho2I + pOverRho2J));
}

// Meteer 2011, eq. 6 divided by ρ_i: -m_j (p_i + p_j) / (2 ρ_i ρ_j) ∇W.
template <class S, class V>
SPH_HD V pressureAccelerationPaper(S massJ, S pressureI, S inverseDensityI, S pressureJ,
                                   S inverseDensityJ, V gradW) {
  return gradW * (S(-0.5f) * massJ * (pressureI + pressureJ) * inverseDensityI * inverseDensityJ);
}

// A wall particle acts as a mirror of the fluid particle (Akinci et al. 2012: mass ρ0 ψ_b,
// density ρ_i) in the symmetric form, at the pressure the fluid would have at the wall
// particle (`wallPressure`, see below). Akinci's eq. 10 keeps only the p_i/ρ_i² half with
// p_b = p_i; that wall is half as stiff, and gives no vertical pressure gradient beside a side
// wall, so a narrow tank's pressure runs 25 % above ρ g h.
template <class S, class V>
SPH_HD V boundaryPressureAcceleration(S boundaryMass, S pressureI, S densityI, S wallPressure,
                                      V gradW) {
  return gradW * (-boundaryMass * (pressureI + wallPressure) / (densityI * densityI));
}

// The fluid's pressure extrapolated hydrostatically from particle i to wall particle b
// (Adami et al. 2012, eq. 27, one neighbour): p_b = p_i + ρ_i g·(x_b - x_i).
template <class S, class V>
SPH_HD S wallPressure(S pressureI, S densityI, V gravity, V xbMinusXi, bool clampNegative) {
  const S p = pressureI + densityI * dot(gravity, xbMinusXi);
  return clampNegative ? select(p < S(0), S(0), p) : p;
}

// Meteer 2011, eq. 7 divided by ρ_i (Müller 2003): μ m_j (v_j - v_i) / (ρ_i ρ_j) ∇²W.
template <class S, class V>
SPH_HD V mullerViscosityAcceleration(S dynamicViscosity, S massJ, S densityI, S densityJ, V vij,
                                     S laplacianW) {
  return vij * (-dynamicViscosity * massJ * laplacianW / (densityI * densityJ));
}

// Monaghan 1992 artificial viscosity (the 2021 CUDA SPH tutorial's form): acts only on
// approaching pairs.
//   a_i = m_j α h c0 (v_ij·r_ij) / (ρ̄_ij (r² + 0.01 h²)) ∇W
template <class S, class V>
SPH_HD V artificialViscosityAcceleration(S alpha, S soundSpeed, S h, S massJ, S densityI,
                                         S densityJ, V vij, V rij, S r2, V gradW) {
  const S approach = dot(vij, rij);
  const S meanDensity = S(0.5f) * (densityI + densityJ);
  const S mu = h * approach / (r2 + S(0.01f) * h * h);
  return gradW * select(approach < S(0), massJ * alpha * soundSpeed * mu / meanDensity, S(0));
}

// Müller et al. 2003 eq. 19 as an acceleration: -σ ∇²c n / (|n| ρ_i), with n = ∇c the colour
// field's gradient, where |n| passes the surface threshold; inside the fluid n is noise, and
// nothing acts.
SPH_HD Vec3 surfaceTensionAcceleration(float sigma, float threshold, Vec3 colourGradient,
                                       float colourLaplacian, float density) {
  const float normalLength = length(colourGradient);
  if (normalLength <= threshold) return Vec3{0.0f, 0.0f, 0.0f};
  return colourGradient * (-sigma * colourLaplacian / (normalLength * density));
}

}  // namespace sph
