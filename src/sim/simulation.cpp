#include "sph/simulation.hpp"

#include "sim/simulation_impl.hpp"

namespace sph {

Simulation::Simulation(const Scene& scene) : impl_(std::make_unique<Impl>(scene)) {}
Simulation::~Simulation() = default;

// Seed 1 §6, in our order: the forces of this step act on the positions they were computed at.
void Simulation::step(double until) {
  Impl& s = *impl_;
  StepProfile& profile = s.profile;
  using detail::timedMs;
  profile.buildGrid = timedMs([&] { s.removed += fluid::buildGrid(s.fluid, s.grid, s.domain); });
  profile.densityPressure =
      timedMs([&] { fluid::computeDensityAndPressure(s.fluid, s.grid, s.boundary, s.params); });
  profile.forces = timedMs([&] { fluid::computeForces(s.fluid, s.grid, s.boundary, s.params); });
  // The interaction with objects (seed 1 §7) goes here.
  profile.timeStep = timedMs([&] { s.dt = s.chooseTimeStep(until); });
  profile.integrate = timedMs([&] { fluid::integrate(s.fluid, float(s.dt), s.domain); });
  s.time = (s.dt == until - s.time) ? until : s.time + s.dt;
  ++s.steps;
}

void Simulation::advanceTo(double t) {
  while (impl_->time < t) step(t);
}

double Simulation::time() const {
  return impl_->time;
}
std::uint64_t Simulation::stepCount() const {
  return impl_->steps;
}
double Simulation::lastDt() const {
  return impl_->dt;
}
std::uint64_t Simulation::removedCount() const {
  return impl_->removed;
}
std::uint64_t Simulation::fluidCount() const {
  return impl_->fluid.count;
}
const Scene& Simulation::scene() const {
  return impl_->scene;
}
const Calibration& Simulation::calibration() const {
  return impl_->calibration;
}
const StepProfile& Simulation::lastProfile() const {
  return impl_->profile;
}

}  // namespace sph
