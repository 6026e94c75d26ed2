// The weakly compressible step: Müller, Charypar & Gross 2003's SPH, with the interaction of
// Meteer 2011 (§6 and §7, in our order). The pressure comes from the density by the equation of
// state and acts in the forces; the forces of the fluid and of the contacts with objects act
// on the positions they were computed at.
#include "sim/simulation_impl.hpp"

namespace sph {

std::vector<Simulation::Impl::Stage> Simulation::Impl::wcsphStages() const {
  std::vector<Stage> list;
  // Across processes: each owns its part's particles and holds its neighbours' as ghosts.
  if (ranks)
    list.push_back({"exchange particles", &StepProfile::exchange, &Impl::exchangeParticles});
  list.push_back({"build grid", &StepProfile::buildGrid, &Impl::buildGrid});
  list.push_back({"density and pressure", &StepProfile::densityPressure, &Impl::sumDensity});
  // The passes skip ghosts: each takes the density its owner computed, for the continuity
  // pass's diffusion as for the forces.
  const Stage ghostDensities{"ghost densities", &StepProfile::exchange, &Impl::refreshGhosts};
  // With continuity the sums only list the neighbours; the density is integrated.
  if (params.continuityDensity) {
    if (ranks) list.push_back(ghostDensities);
    list.push_back({"continuity density", &StepProfile::densityPressure, &Impl::advanceDensity});
  }
  if (ranks) list.push_back(ghostDensities);
  list.push_back({"forces", &StepProfile::forces, &Impl::computeForces});
  if (coupling.coupled())
    list.push_back({"contacts with objects", &StepProfile::interaction, &Impl::contactObjects});
  list.push_back({"time step", &StepProfile::timeStep, &Impl::chooseTimeStep});
  if (coupling.coupled())
    list.push_back({"forces on objects", &StepProfile::interaction, &Impl::collectObjectForces});
  addStepEnd(list, {"integrate", &StepProfile::integrate, &Impl::integrate});
  return list;
}

}  // namespace sph
