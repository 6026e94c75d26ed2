// The time step of each step, from the bounds of the solver and the objects, and the guard
// against a run that has failed: a NaN, an infinity, compression past failure.max_density_error,
// a runaway speed, or a step that has shrunk to nothing.
#pragma once

#include <cstdint>

#include "sim/decomposition.hpp"
#include "sim/fluid_engine.hpp"
#include "sph/calibration.hpp"
#include "sph/scene.hpp"

namespace sph::sim {

// Where a run is in time.
struct Clock {
  double time = 0.0;
  double dt = 0.0;     // the step being taken, or the last one
  double until = 0.0;  // the step being taken may not pass it
  // Continuity density: advanced at the next density pass over the step that moved the
  // particles (none before the first).
  double movedFor = 0.0;
  std::uint64_t steps = 0;
};

// The fluid's counts since the start.
struct RunCounts {
  std::uint64_t initialFluid = 0;
  std::uint64_t removed = 0;  // left the domain
  std::uint64_t clamped = 0;  // speeds limited by the integrator
};

// The shortest time.fixed_dt a scene may ask for: a step shorter than it is a blow-up.
constexpr double kShortestStep = 1e-9;  // s

// The next step: the longest the solver's bounds and objectStep (HUGE_VAL without objects)
// allow, landing exactly on clock.until rather than leaving a sliver of a step for later.
// A run that has failed throws SimulationFailure naming the step, the particle and the
// quantity; the state is left as the last good step made it. In a distributed run (`ranks`)
// the measures are every process's, so all take the same step or all fail with the same message.
double nextTimeStep(const Scene& scene, const Calibration& calibration, FluidEngine& engine,
                    const Clock& clock, const RunCounts& counts, double objectStep,
                    Decomposition* ranks = nullptr);

}  // namespace sph::sim
