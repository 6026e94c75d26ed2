#include "sph/simulation.hpp"

#include <stdexcept>
#include <string>

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
  profile.integrate =
      timedMs([&] { s.clamped += fluid::integrate(s.fluid, float(s.dt), s.domain); });
  s.time = (s.dt == until - s.time) ? until : s.time + s.dt;
  ++s.steps;
}

void Simulation::setExternalAcceleration(const std::vector<float>& byId) {
  fluid::FluidParticles& f = impl_->fluid;
  if (byId.empty()) {
    f.externalById.resize(0);
    return;
  }
  const std::size_t n = impl_->initialFluid;
  if (byId.size() != 3 * n)
    throw std::invalid_argument("setExternalAcceleration: expected 3 × " + std::to_string(n) +
                                " values (x, y, z per fluid particle), got " +
                                std::to_string(byId.size()));
  f.externalById.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    f.externalById[i] = Vec4{byId[3 * i], byId[3 * i + 1], byId[3 * i + 2], 0.0f};
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
std::uint64_t Simulation::clampedCount() const {
  return impl_->clamped;
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
