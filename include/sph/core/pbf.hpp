// Position Based Fluids (Macklin & Müller, "Position Based Fluids", ACM Transactions on Graphics
// 32(4), SIGGRAPH 2013). Each fluid particle carries a density constraint on the predicted
// positions x*,
//   C_i = ρ_i/ρ0 - 1 ≤ 0,   ρ_i = Σ_j m_j W_ij + Σ_b ρ0 ψ_b W_ib,
// kept one-sided (a particle short of neighbours, at the free surface, is not pulled towards
// them; the tensile correction below keeps it from clustering). A Jacobi iteration moves each
// particle by
//   Δx_i = Σ_j V_j (λ_i + λ_j + s_corr,ij) ∇W_ij + Σ_b ψ_b 2 λ_i ∇W_ib,
// with V_j = m_j/ρ0, a wall particle mirroring λ_i as in the incompressible solver
// (core/dfsph.hpp), and the multiplier
//   λ_i = -C_i / (Σ_k |∇_k C_i|² + ε),
// whose denominator is that solver's: (G + G_w)·G + Σ_j |V_j ∇W_ij|², G = Σ_j V_j ∇W_ij (walls
// included), G_w the walls' part. ε, the constraint's relaxation, keeps a particle with almost
// no neighbours from an unbounded move.
//
// Each pair term is written once for a float and a Vec3 and for a SIMD batch (S, V as in
// core/momentum.hpp).
#pragma once

#include "sph/core/select.hpp"
#include "sph/core/vec.hpp"

namespace sph {

// The sum a constraint's gradient makes, (G + G_w)·G + Σ_j |V_j ∇W_ij|².
SPH_HD float pbfGradientSquares(Vec3 volumeGradientSum, Vec3 wallGradientSum,
                                float volumeGradientSquares) {
  return dot(volumeGradientSum + wallGradientSum, volumeGradientSum) + volumeGradientSquares;
}

// λ_i for density ρ_i: zero where the particle is not compressed.
SPH_HD float pbfMultiplier(float density, float restDensity, float gradientSquares,
                           float relaxation) {
  const float c = density / restDensity - 1.0f;
  return c > 0.0f ? -c / (gradientSquares + relaxation) : 0.0f;
}

// Macklin & Müller's artificial pressure, s_corr = -k (W(r)/W(Δq))^n with n = 4: a small
// repulsion between close pairs that a free surface's particles, whose constraint is inactive,
// would otherwise let cluster. `wOverWq` is W(r)/W(Δq); `strength` is k in the multipliers'
// units (1/m², as 1/(Σ|∇C|²)): the scene's k over the gradient sum of a full lattice.
template <class S>
SPH_HD S pbfTensileCorrection(S strength, S wOverWq) {
  const S q2 = wOverWq * wOverWq;
  return -strength * q2 * q2;
}

// One fluid neighbour's share of Δx_i.
template <class S, class V>
SPH_HD V pbfDisplacementTerm(S volumeJ, S lambdaI, S lambdaJ, S tensile, V gradW) {
  return gradW * (volumeJ * (lambdaI + lambdaJ + tensile));
}

// The walls' share of Δx_i, each wall particle mirroring λ_i: 2 λ_i G_w.
SPH_HD Vec3 pbfWallDisplacement(float lambdaI, Vec3 wallGradientSum) {
  return wallGradientSum * (2.0f * lambdaI);
}

// XSPH (Monaghan 1989), Macklin & Müller's viscosity: one neighbour's share of
// the velocity's smoothing, c V (v_j - v_i) W_ij, with V = m/ρ0 the same for both particles
// of a pair so that the two shares are opposite and momentum stays (m/ρ_j would not).
template <class S, class V>
SPH_HD V xsphTerm(S coefficient, S volume, V vji, S w) {
  return vji * (coefficient * volume * w);
}

// The pressure the multipliers stand for. Δx = -Δt² ∇p/ρ over a step, and the symmetric
// pressure force's p_i/ρ_i² m_j ∇W against PBF's V_j λ_i ∇W gives p_i = -λ_i ρ_i²/(ρ0 Δt²); with
// ρ_i at ρ0, and λ summed over a substep's iterations (each moves the particles further):
SPH_HD float pbfPressure(float multiplierSum, float restDensity, float dt) {
  return -multiplierSum * restDensity / (dt * dt);
}

}  // namespace sph
