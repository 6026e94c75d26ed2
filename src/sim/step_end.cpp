// How every solver's step ends, once its forces and time step are known: what the probes
// measure of the walls, the flow in, the move, the objects' own step, and the probes.
#include "sim/simulation_impl.hpp"

namespace sph {

void Simulation::Impl::addStepEnd(std::vector<Stage>& list) const {
  if (!wallOfParticle.empty())  // a force probe on a wall
    list.push_back({"forces on walls", &StepProfile::wallForces, &Impl::collectWallForces});
  if (!emitters.empty()) list.push_back({"drive inflow", &StepProfile::flow, &Impl::driveInflow});
  list.push_back({"integrate", &StepProfile::integrate, &Impl::integrate});
  if (coupled()) list.push_back({"object step", &StepProfile::objects, &Impl::advanceObjects});
  if (!emitters.empty()) list.push_back({"emit", &StepProfile::flow, &Impl::emit});
  if (!probes->empty()) list.push_back({"probes", &StepProfile::probes, &Impl::sampleProbes});
}

void Simulation::Impl::sampleProbes() {
  if (probes->empty()) return;
  probes->record(time, engine->samplePoints(probes->points()),
                 {fluidForceOnObject, contactForceOnObject, fluidForceOnWall});
}

void Simulation::Impl::collectWallForces() {
  const std::vector<Vec4> force = engine->wallForces();
  std::vector<double> sum(3 * fluidForceOnWall.size(), 0.0);
  for (std::size_t k = 0; k < force.size(); ++k) {
    if (wallOfParticle[k] >= fluidForceOnWall.size()) continue;  // a periodic image
    double* s = &sum[3 * wallOfParticle[k]];
    s[0] += force[k].x;
    s[1] += force[k].y;
    s[2] += force[k].z;
  }
  for (std::size_t w = 0; w < fluidForceOnWall.size(); ++w)
    fluidForceOnWall[w] = Vec3{float(sum[3 * w]), float(sum[3 * w + 1]), float(sum[3 * w + 2])};
}

void Simulation::Impl::emit() {
  const sim::NewParticles fresh = emitters.emit(time);
  if (fresh.position.empty()) return;
  engine->addParticles(fresh.position, fresh.velocity, nextId);
  nextId += std::uint32_t(fresh.position.size());
}

}  // namespace sph
