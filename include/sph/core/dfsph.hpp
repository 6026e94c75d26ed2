// The incompressible solver: divergence-free SPH (Bender & Koschier, "Divergence-Free Smoothed
// Particle Hydrodynamics", SCA 2015, and "Divergence-Free SPH for Incompressible and Viscous
// Fluids", TVCG 2017). Two Jacobi solvers correct the velocities: one until the velocity field
// compresses nothing, one until the density predicted at the end of the step is the rest
// density.
//
// Each corrects velocities as a symmetric pressure force would, from a per-particle K_i that
// plays the part of p_i/ρ_i² (Bender's κ_i/ρ_i):
//   Δv_i = -Δt Σ_j m_j (K_i + K_j) ∇W_ij  (pressureAccelerationSymmetric, momentum.hpp)
// and K_i is chosen so that, were the neighbours' K zero, particle i alone would undo its
// predicted density error e_i = ρ*_i/ρ0 - 1:
//   K_i = e_i β_i / (ρ0 Δt²)
// with volumes V_j = m_j/ρ0 for fluid and ψ_b for walls. A wall particle mirrors the fluid
// particle (K_b = K_i, Akinci et al. 2012, with the hydrostatic part of Adami et al. 2012 added
// among the other forces), so that a tank's pressure is ρ g h beside its side walls too; with
// K_b = 0 (Bender & Koschier's choice) a resting tank 10 particles wide read 10-17 % above it.
// Walls do not move, so Δv_i = -Δt K_i ρ0 (G + G_w) with G = Σ_j V_j ∇W_ij over fluid and
// walls and G_w over the walls alone, and the density's response to K_i gives
//   β_i = 1 / ((G + G_w)·G + Σ_fluid |V_j ∇W_ij|²)
#pragma once

#include "sph/core/continuity.hpp"
#include "sph/core/select.hpp"
#include "sph/core/vec.hpp"

namespace sph {

// β_i from G = Σ_j V_j ∇W_ij (walls included), G_w (walls alone) and Σ_fluid |V_j ∇W_ij|². A
// particle with almost no neighbours (the sum below `smallest`) has no density to correct: 0.
SPH_HD float dfsphFactor(Vec3 volumeGradientSum, Vec3 wallGradientSum, float volumeGradientSquares,
                         float smallest) {
  const float d =
      dot(volumeGradientSum + wallGradientSum, volumeGradientSum) + volumeGradientSquares;
  return d > smallest ? 1.0f / d : 0.0f;
}

// The smallest sum dfsphFactor takes, for support radius h: a full neighbourhood gives about
// 1.7/h² (cubic spline, h = 2d), a particle with one neighbour near the edge of its support
// orders of magnitude less.
inline float dfsphSmallestFactorSum(float h) {
  return 1e-3f / (h * h);
}

// K_i for a relative density error e_i (Δt: the step the error is predicted over).
SPH_HD float dfsphStiffness(float relativeError, float factor, float restDensity, float dt) {
  return relativeError * factor / (restDensity * dt * dt);
}

}  // namespace sph
