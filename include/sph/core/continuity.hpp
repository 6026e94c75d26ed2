// The density's rate of change (the continuity equation) and the density diffusion of δ-SPH,
// per neighbour: what the incompressible solver predicts density with, and what the weakly
// compressible solver integrates its density by when the scene asks for "continuity".
#pragma once

#include "sph/core/select.hpp"
#include "sph/core/vec.hpp"

namespace sph {

// One neighbour's share of the density's rate of change at particle i,
// Dρ_i/Dt = Σ_j m_j (v_i - v_j)·∇W_ij; a wall particle has v = 0 and m = ρ0 ψ_b.
template <class S, class V>
SPH_HD S densityRateTerm(S massJ, V vij, V gradW) {
  return massJ * dot(vij, gradW);
}

// One fluid neighbour's share of the density diffusion of δ-SPH (Molteni & Colagrossi, "A
// simple procedure to improve the pressure evaluation in hydrodynamic context using the SPH",
// 2009), its density difference less the hydrostatic one (Fourtakas et al., "Local uniform
// stencil (LUST) boundary condition ...", 2019), so that water at rest under gravity does not
// diffuse:
//   δ h c0 Σ_j 2 (ρ_j - ρ_i - Δρ^H_ji) ((x_j - x_i)·∇_i W_ij) / |x_ij|² · m_j / ρ_j,
//   Δρ^H_ji = -ρ0 g·(x_i - x_j) / c0²   (the pressure ρ0 g·x over the stiffness c0²).
// `coefficient` is δ h c0; rij = x_i - x_j, r2 = |rij|² (not zero: gradW is zero where the
// pair is not a neighbour, and r2 then anything positive).
template <class S, class V>
SPH_HD S densityDiffusionTerm(S coefficient, S densityI, S densityJ, S massJ, V rij, S r2, V gradW,
                              V gravity, S restDensity, S soundSpeed) {
  const S dynamic =
      densityJ - densityI + restDensity * dot(gravity, rij) / (soundSpeed * soundSpeed);
  return coefficient * S(-2.0f) * dynamic * dot(rij, gradW) / r2 * massJ / densityJ;
}

}  // namespace sph
