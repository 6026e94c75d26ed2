// How every solver's step ends, once its forces and time step are known: what the probes
// measure of the walls, the flow in, the solver's own move, the objects' own step, and the
// probes.
#include "sim/simulation_impl.hpp"

namespace sph {

void Simulation::Impl::addStepEnd(std::vector<Stage>& list, const Stage& move) const {
  if (!outputs.wallOfParticle.empty())  // a force probe on a wall
    list.push_back({"forces on walls", &StepProfile::wallForces, &Impl::collectWallForces});
  if (!inflow.emitters.empty())
    list.push_back({"drive inflow", &StepProfile::flow, &Impl::driveInflow});
  list.push_back(move);
  if (coupling.coupled())
    list.push_back({"object step", &StepProfile::objects, &Impl::advanceObjects});
  if (!inflow.emitters.empty()) list.push_back({"emit", &StepProfile::flow, &Impl::emit});
  if (!outputs.probes->empty())
    list.push_back({"probes", &StepProfile::probes, &Impl::sampleProbes});
}

}  // namespace sph
