// The incompressible solver's last solves, and its counts since the start.
#pragma once

#include <cstdint>

#include "fluid/dfsph_settings.hpp"

namespace sph::sim {

struct SolverRecord {
  fluid::SolverReport divergence;
  fluid::SolverReport density;
  std::uint64_t densityIterations = 0;
  std::uint64_t divergenceIterations = 0;
  std::uint64_t unconvergedSolves = 0;

  // asked: the scene asked for the solve (fluid.dfsph.divergence_solve); left out, it still
  // made its first pass, which cannot fail to converge.
  void addDivergence(const fluid::SolverReport& report, bool asked) {
    divergence = report;
    divergenceIterations += std::uint64_t(report.iterations);
    if (!asked) divergence.converged = true;
    if (!divergence.converged) ++unconvergedSolves;
  }
  void addDensity(const fluid::SolverReport& report) {
    density = report;
    densityIterations += std::uint64_t(report.iterations);
    if (!density.converged) ++unconvergedSolves;
  }
};

}  // namespace sph::sim
