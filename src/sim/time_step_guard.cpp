// The time step of each step, from the bounds of the solver and the objects, and the guard
// against a run that has failed: a NaN, an infinity, compression past failure.max_density_error,
// a runaway speed, or a step that has shrunk to nothing. A failure names the step, the particle
// and the quantity; the state is left as the last good step made it.
#include "sim/simulation_impl.hpp"

namespace sph {

double Simulation::Impl::nextTimeStep(double until) {
  const fluid::StepMeasures m = engine->measureStep();
  const float bound = static_cast<float>(scene.failure.maxDensityError);
  if (!m.finite || m.maxDensityError > bound) fail(bound);
  // Past the scene's bound, by default ten times the speed of sound, or no fluid left at all:
  // a blow-up the density bound did not catch (a fixed step too long for the stiffness), not
  // a result.
  const double speedLimit = scene.failure.maxSpeed.value_or(
      10.0 * std::max(calibration.soundSpeed, 10.0 * calibration.maxExpectedSpeed));
  // A scene with flow in or out may run empty.
  const bool flows = !scene.emitters.empty() || !scene.outlets.empty();
  if (m.maxSpeed > speedLimit || (engine->fluidCount() == 0 && initialFluid > 0 && !flows))
    failRunaway(m, speedLimit);
  double next = scene.time.fixedDt
                    ? *scene.time.fixedDt
                    : longestStep(sim::stepLimits(scene, calibration), m.maxSpeed,
                                  m.maxAcceleration, coupled() ? objectTimeStep() : HUGE_VAL);
  const double remaining = until - time;
  // Under a nanosecond (the shortest time.fixed_dt a scene may ask for) the fluid has blown
  // up: its speeds or accelerations are beyond any scene's, and the run would crawl forever
  // or, once the step no longer moves the clock, hang.
  if (next < kShortestStep && next < remaining) failStalled(next, m);
  // Land exactly on `until` rather than leave a sliver of a step for later.
  if (next >= remaining)
    next = remaining;
  else if (next > 0.5 * remaining)
    next = 0.5 * remaining;
  return next;
}

double Simulation::Impl::objectTimeStep() const {
  const double travel = travelTimeStep(0.25 * interactionParams.fluidRadius, objectMaxSpeed);
  if (interactionParams.boundary) return travel;  // no contact springs
  // The stiffest contact is at the centre of the influence sphere, where φ = e^β.
  const double contact = springTimeStep(calibration.mass, calibration.contactStiffness,
                                        distanceFunctionPeak(scene.interaction.distanceExponent));
  return std::min(contact, travel);
}

void Simulation::Impl::failStalled(double dt, const fluid::StepMeasures& m) {
  std::ostringstream message;
  message << "simulation failed at step " << steps << " (t = " << time
          << " s): the time step fell to " << dt << " s, under " << kShortestStep
          << " s: the fastest particle moves at " << m.maxSpeed
          << " m/s, the largest acceleration is " << m.maxAcceleration << " m/s^2";
  throw SimulationFailure(message.str(), steps, 0, "time step");
}

void Simulation::Impl::failRunaway(const fluid::StepMeasures& m, double speedLimit) {
  std::ostringstream message;
  message << "simulation failed at step " << steps << " (t = " << time << " s): ";
  if (engine->fluidCount() == 0) {
    message << "every fluid particle has left the domain (" << removed << " removed)";
    throw SimulationFailure(message.str(), steps, 0, "fluid count");
  }
  const sim::HostParticles fluid = engine->download();  // once, on the way out
  std::size_t fastest = 0;
  for (std::size_t i = 1; i < fluid.id.size(); ++i)
    if (lengthSquared(xyz(fluid.velocity[i])) > lengthSquared(xyz(fluid.velocity[fastest])))
      fastest = i;
  message << "particle " << fluid.id[fastest] << ": speed = " << m.maxSpeed
          << (scene.failure.maxSpeed ? " m/s, past failure.max_speed ("
                                     : " m/s, past ten times the speed of sound (")
          << speedLimit << " m/s)";
  throw SimulationFailure(message.str(), steps, fluid.id[fastest], "speed");
}

void Simulation::Impl::fail(float bound) {
  const fluid::BadParticle bad = engine->findBadParticle(bound);
  std::ostringstream message;
  message << "simulation failed at step " << steps << " (t = " << time << " s): particle " << bad.id
          << ": " << bad.quantity << " = " << bad.value;
  if (bad.pastBound) message << ", past failure.max_density_error = " << bound;
  throw SimulationFailure(message.str(), steps, bad.id, bad.quantity);
}

}  // namespace sph
