// The incompressible step: Divergence-Free SPH (Bender & Koschier 2015 and 2017), with the
// objects as boundary particles of its pressure (Akinci et al. 2012) or as contact partners
// (Meteer 2011, §7). The divergence solve first makes the velocity field divergence-free; the
// density solve, after the other forces, gives the pressure that keeps the density at rest at
// the end of the step.
#include <cmath>

#include "sim/simulation_impl.hpp"
#include "sph/core/constants.hpp"

namespace sph {

std::vector<Simulation::Impl::Stage> Simulation::Impl::dfsphStages() const {
  std::vector<Stage> list;
  // Boundary particles are read before the density pass that counts them.
  if (coupling.asBoundary())
    list.push_back({"objects as boundary", &StepProfile::interaction, &Impl::receiveObjects});
  // Across processes (as in the weakly compressible step), and the solves' ghosts refreshed
  // after each of their passes (fluid::SolverGhosts).
  if (ranks)
    list.push_back({"exchange particles", &StepProfile::exchange, &Impl::exchangeParticles});
  list.push_back({"build grid", &StepProfile::buildGrid, &Impl::buildGrid});
  list.push_back({"density", &StepProfile::densityPressure, &Impl::sumDensity});
  if (ranks) list.push_back({"ghost densities", &StepProfile::exchange, &Impl::refreshGhosts});
  // Left out by the scene, it still makes its first pass: the step's factors, which the
  // density solve needs, and the error it reports.
  list.push_back({"divergence solve", &StepProfile::divergenceSolve, &Impl::solveDivergence});
  list.push_back({"non-pressure forces", &StepProfile::forces, &Impl::computeForces});
  if (coupling.asBoundary())
    list.push_back({"containment", &StepProfile::interaction, &Impl::checkContainment});
  else if (coupling.coupled())
    list.push_back({"contacts with objects", &StepProfile::interaction, &Impl::contactObjects});
  list.push_back({"time step", &StepProfile::timeStep, &Impl::chooseTimeStep});
  if (scene.fluid.dfsph.densitySolve)
    list.push_back({"density solve", &StepProfile::densitySolve, &Impl::solveDensity});
  // With boundary coupling, the reactions of the pressure the solves have just given.
  if (coupling.coupled())
    list.push_back({"forces on objects", &StepProfile::interaction, &Impl::collectObjectForces});
  addStepEnd(list, {"integrate", &StepProfile::integrate, &Impl::integrate});
  return list;
}

void Simulation::Impl::solveDivergence() {
  engine->prepareSolver();
  solves.addDivergence(engine->solve(solverSettings(fluid::SolverTarget::NoDivergence),
                                     fluid::SolverTarget::NoDivergence, float(clock.dt)),
                       scene.fluid.dfsph.divergenceSolve);
}

void Simulation::Impl::solveDensity() {
  solves.addDensity(engine->solve(solverSettings(fluid::SolverTarget::RestDensity),
                                  fluid::SolverTarget::RestDensity, float(clock.dt)));
}

fluid::SolverSettings Simulation::Impl::solverSettings(fluid::SolverTarget target) const {
  const DfsphDesc& d = scene.fluid.dfsph;
  fluid::SolverSettings s;
  s.tolerance = float(target == fluid::SolverTarget::RestDensity ? d.densityTolerance
                                                                 : d.divergenceTolerance);
  s.minIterations = d.minIterations;
  s.maxIterations = d.maxIterations;
  // Left out, the divergence solve still makes its first pass: the factors and the walls'
  // gradients of the step, which the density solve needs, and the error it reports.
  if (target == fluid::SolverTarget::NoDivergence && !d.divergenceSolve)
    s.minIterations = s.maxIterations = 0;
  s.warmStart = d.warmStart;
  s.coarseShare = float(d.coarseCorrection);
  // The coarse level is one solve over the whole fluid: not yet across processes.
  if (ranks) {
    s.coarseShare = 0.0f;
    s.ghosts = &ranks->solverGhosts();
  }
  // Six tenths of a full neighbourhood on the initial lattice: (4/3) π (h/d)³ neighbours.
  const double ratio = scene.fluid.supportRatio;
  s.minNeighbours = std::uint32_t(std::lround(0.6 * 4.0 / 3.0 * kPi * ratio * ratio * ratio));
  return s;
}

}  // namespace sph
