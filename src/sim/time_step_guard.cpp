#include "sim/time_step_guard.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim/calibration.hpp"
#include "sph/core/time_step.hpp"
#include "sph/error.hpp"

namespace sph::sim {

namespace {

[[noreturn]] void failStalled(const Clock& clock, double dt, const fluid::StepMeasures& m) {
  std::ostringstream message;
  message << "simulation failed at step " << clock.steps << " (t = " << clock.time
          << " s): the time step fell to " << dt << " s, under " << kShortestStep
          << " s: the fastest particle moves at " << m.maxSpeed
          << " m/s, the largest acceleration is " << m.maxAcceleration << " m/s^2";
  throw SimulationFailure(message.str(), clock.steps, 0, "time step");
}

// The fastest particle: of every process in a distributed run (the lowest id among equals).
std::uint32_t fastestParticle(FluidEngine& engine, Decomposition* ranks) {
  const HostParticles fluid = engine.download();  // once, on the way out
  fluid::BadParticle fastest;
  for (std::size_t i = 0; i < fluid.id.size(); ++i) {
    if (fluid::isGhost(fluid.id[i])) continue;
    const float speed = length(xyz(fluid.velocity[i]));
    if (!fastest.found || speed > fastest.value ||
        (speed == fastest.value && fluid.id[i] < fastest.id))
      fastest = {true, fluid.id[i], "speed", speed};
  }
  if (!ranks) return fastest.id;
  const double top = ranks->max(fastest.found ? double(fastest.value) : -1.0);
  fastest.found = fastest.found && double(fastest.value) == top;
  return ranks->combine(fastest).id;
}

[[noreturn]] void failRunaway(const Scene& scene, FluidEngine& engine, const Clock& clock,
                              const RunCounts& counts, const fluid::StepMeasures& m,
                              double speedLimit, std::uint64_t fluidCount, Decomposition* ranks) {
  std::ostringstream message;
  message << "simulation failed at step " << clock.steps << " (t = " << clock.time << " s): ";
  if (fluidCount == 0) {
    message << "every fluid particle has left the domain (" << counts.removed << " removed)";
    throw SimulationFailure(message.str(), clock.steps, 0, "fluid count");
  }
  const std::uint32_t fastest = fastestParticle(engine, ranks);
  message << "particle " << fastest << ": speed = " << m.maxSpeed
          << (scene.failure.maxSpeed ? " m/s, past failure.max_speed ("
                                     : " m/s, past ten times the speed of sound (")
          << speedLimit << " m/s)";
  throw SimulationFailure(message.str(), clock.steps, fastest, "speed");
}

[[noreturn]] void failBadParticle(FluidEngine& engine, const Clock& clock, float bound,
                                  Decomposition* ranks) {
  fluid::BadParticle bad = engine.findBadParticle(bound);
  if (ranks) bad = ranks->combine(bad);
  std::ostringstream message;
  message << "simulation failed at step " << clock.steps << " (t = " << clock.time
          << " s): particle " << bad.id << ": " << bad.quantity << " = " << bad.value;
  if (bad.pastBound) message << ", past failure.max_density_error = " << bound;
  throw SimulationFailure(message.str(), clock.steps, bad.id, bad.quantity);
}

}  // namespace

double nextTimeStep(const Scene& scene, const Calibration& calibration, FluidEngine& engine,
                    const Clock& clock, const RunCounts& counts, double objectStep,
                    Decomposition* ranks) {
  const fluid::StepMeasures m = ranks ? ranks->combine(engine.measureStep()) : engine.measureStep();
  const float bound = static_cast<float>(scene.failure.maxDensityError);
  if (!m.finite || m.maxDensityError > bound) failBadParticle(engine, clock, bound, ranks);
  // Past the scene's bound, by default ten times the speed of sound, or no fluid left at all:
  // a blow-up the density bound did not catch (a fixed step too long for the stiffness), not
  // a result.
  const double speedLimit = scene.failure.maxSpeed.value_or(
      10.0 * std::max(calibration.soundSpeed, 10.0 * calibration.maxExpectedSpeed));
  // A scene with flow in or out may run empty.
  const bool flows = !scene.emitters.empty() || !scene.outlets.empty();
  const std::uint64_t fluidCount =
      ranks ? ranks->sum(std::uint64_t(engine.fluidCount())) : engine.fluidCount();
  if (m.maxSpeed > speedLimit || (fluidCount == 0 && counts.initialFluid > 0 && !flows))
    failRunaway(scene, engine, clock, counts, m, speedLimit, fluidCount, ranks);
  // The position solver's substeps are fixed: its constraints hold at any step, and its
  // substeps keep each particle's move a fraction of its radius at the expected speeds.
  double next =
      scene.time.fixedDt ? *scene.time.fixedDt
      : scene.fluid.solver == FluidSolver::Pbf
          ? scene.time.frameDt / calibration.substeps
          : longestStep(stepLimits(scene, calibration), m.maxSpeed, m.maxAcceleration, objectStep);
  const double remaining = clock.until - clock.time;
  // Under a nanosecond the fluid has blown up: its speeds or accelerations are beyond any
  // scene's, and the run would crawl forever or, once the step no longer moves the clock, hang.
  if (next < kShortestStep && next < remaining) failStalled(clock, next, m);
  if (scene.fluid.solver == FluidSolver::Pbf && !scene.time.fixedDt && next < remaining) {
    // Equal substeps up to `until`: the multipliers' pressure, -ρ0 Σλ/Δt², reads what is left
    // of the last substep's compression over Δt², which a sliver of a step would magnify.
    const double substeps = std::ceil(remaining / next * (1.0 - 1e-9));
    return substeps < 1e9 ? remaining / substeps : next;  // an `until` far off: no landing
  }
  if (next >= remaining)
    next = remaining;
  else if (next > 0.5 * remaining)
    next = 0.5 * remaining;
  return next;
}

}  // namespace sph::sim
