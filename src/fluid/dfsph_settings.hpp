// What a solve of the incompressible solver is asked for and what it reports (dfsph_solve.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace sph::fluid {

// What the predicted error is measured against.
enum class SolverTarget {
  RestDensity,  // the density at the end of the step: ρ_i + Δt Dρ_i/Dt = ρ0
  NoDivergence  // the velocity field: Dρ_i/Dt = 0
};

struct SolverSettings {
  float tolerance = 0.0f;  // the average relative density error to stop at
  int minIterations = 0;
  int maxIterations = 0;
  bool warmStart = true;
  // Particles with fewer listed neighbours than this (the free surface) are left alone by the
  // divergence solve: their deficient neighbourhoods read as expansion.
  std::uint32_t minNeighbours = 0;
  // The share of the coarse level's K (coarse_pressure.hpp) the density solve adds to its first
  // iteration; 0: none.
  float coarseShare = 0.0f;
};

struct SolverReport {
  int iterations = 0;         // velocity corrections after the warm start
  float averageError = 0.0f;  // relative, after the last iteration
  float largestError = 0.0f;  // of one particle
  bool converged = true;      // the tolerance met within the iterations allowed
  std::size_t clamped = 0;    // the position solver: particles whose speed its guard limited
};

}  // namespace sph::fluid
