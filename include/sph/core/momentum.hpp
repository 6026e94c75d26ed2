// Pairwise accelerations of the momentum equation. `gradW` is ∇_i W(x_i - x_j); `rij` is
// x_i - x_j, `vij` is v_i - v_j. Each pair term is antisymmetric when multiplied by the mass
// of i, so a sum over all pairs conserves linear momentum.
#pragma once

#include "sph/core/vec.hpp"

namespace sph {

// The per-particle factor of the symmetric form, p/ρ², computed once per particle.
SPH_HD float pressureOverDensitySquared(float pressure, float density) {
  return pressure / (density * density);
}

// Seed 2's symmetric form: -m_j (p_i/ρ_i² + p_j/ρ_j²) ∇W, from the per-particle factors.
SPH_HD Vec3 pressureAccelerationSymmetric(float massJ, float pOverRho2I, float pOverRho2J,
                                          Vec3 gradW) {
  return gradW * (-massJ * (pOverRho2I + pOverRho2J));
}

// Seed 1 eq. 6 divided by ρ_i: -m_j (p_i + p_j) / (2 ρ_i ρ_j) ∇W.
SPH_HD Vec3 pressureAccelerationPaper(float massJ, float pressureI, float inverseDensityI,
                                      float pressureJ, float inverseDensityJ, Vec3 gradW) {
  return gradW * (-0.5f * massJ * (pressureI + pressureJ) * inverseDensityI * inverseDensityJ);
}

// A wall particle acts as a mirror of the fluid particle (Akinci et al. 2012: mass ρ0 ψ_b,
// density ρ_i) in the symmetric form, at the pressure the fluid would have at the wall
// particle (`wallPressure`, see below). Akinci's eq. 10 keeps only the p_i/ρ_i² half with
// p_b = p_i; that wall is half as stiff, and gives no vertical pressure gradient beside a side
// wall, so a narrow tank's pressure runs 25 % above ρ g h.
SPH_HD Vec3 boundaryPressureAcceleration(float boundaryMass, float pressureI, float densityI,
                                         float wallPressure, Vec3 gradW) {
  return gradW * (-boundaryMass * (pressureI + wallPressure) / (densityI * densityI));
}

// The fluid's pressure extrapolated hydrostatically from particle i to wall particle b
// (Adami et al. 2012, eq. 27, one neighbour): p_b = p_i + ρ_i g·(x_b - x_i).
SPH_HD float wallPressure(float pressureI, float densityI, Vec3 gravity, Vec3 xbMinusXi,
                          bool clampNegative) {
  const float p = pressureI + densityI * dot(gravity, xbMinusXi);
  return (clampNegative && p < 0.0f) ? 0.0f : p;
}

// Seed 1 eq. 7 divided by ρ_i (Müller 2003): μ m_j (v_j - v_i) / (ρ_i ρ_j) ∇²W.
SPH_HD Vec3 mullerViscosityAcceleration(float dynamicViscosity, float massJ, float densityI,
                                        float densityJ, Vec3 vij, float laplacianW) {
  return vij * (-dynamicViscosity * massJ * laplacianW / (densityI * densityJ));
}

// Monaghan 1992 artificial viscosity (seed 2's form): acts only on approaching pairs.
//   a_i = m_j α h c0 (v_ij·r_ij) / (ρ̄_ij (r² + 0.01 h²)) ∇W
SPH_HD Vec3 artificialViscosityAcceleration(float alpha, float soundSpeed, float h, float massJ,
                                            float densityI, float densityJ, Vec3 vij, Vec3 rij,
                                            float r2, Vec3 gradW) {
  const float approach = dot(vij, rij);
  if (approach >= 0.0f) return Vec3{0.0f, 0.0f, 0.0f};
  const float meanDensity = 0.5f * (densityI + densityJ);
  const float mu = h * approach / (r2 + 0.01f * h * h);
  return gradW * (massJ * alpha * soundSpeed * mu / meanDensity);
}

}  // namespace sph
