// What a solve of the incompressible solver is asked for and what it reports (dfsph_solve.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sph::fluid {

// A distributed run's ghosts (particles.hpp) in an iterating solve: after each pass the ghosts'
// rows take the values their owners' rows have just been given, and the solve's error is every
// process's, so that every process iterates as one would. The transport is the caller's
// (sim/decomposition.hpp).
class SolverGhosts {
 public:
  virtual ~SolverGhosts() = default;
  // The rows whose values other processes hold as ghosts, and this process's ghosts' rows, in
  // the orders exchange takes and gives their values.
  virtual const std::vector<std::uint32_t>& sentRows() const = 0;
  virtual const std::vector<std::uint32_t>& ghostRows() const = 0;
  // `width` values for each sent row; returns `width` values for each ghost row. Collective.
  virtual std::vector<float> exchange(const std::vector<float>& sent, std::uint32_t width) = 0;
  // This process's error sum, particles counted and largest error in, every process's out.
  // Collective.
  virtual void reduce(std::uint64_t& sum, std::uint64_t& count, std::uint64_t& largest) = 0;
};

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
  // A distributed run's; none in one process.
  SolverGhosts* ghosts = nullptr;
};

struct SolverReport {
  int iterations = 0;         // velocity corrections after the warm start
  float averageError = 0.0f;  // relative, after the last iteration
  float largestError = 0.0f;  // of one particle
  bool converged = true;      // the tolerance met within the iterations allowed
  std::size_t clamped = 0;    // the position solver: particles whose speed its guard limited
};

}  // namespace sph::fluid
