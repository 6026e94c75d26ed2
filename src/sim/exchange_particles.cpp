// The stages of a run across processes (sim/decomposition.hpp): before the grid, the particles
// move to the processes that own them now and the ghosts arrive; after the density pass, the
// ghosts take their owners' densities, so that every force a process computes for its own
// particles is the one a single process would compute.
#include <stdexcept>
#include <string>

#include "sim/simulation_impl.hpp"

namespace sph {

void Simulation::Impl::exchangeParticles() {
  sim::HostFluidState state = engine->downloadState();
  const fluid::DomainParameters domain = sim::domainParameters(scene);
  sim::ExchangeSettings settings;
  settings.reach = params.h;
  settings.domainMin = domain.min;
  settings.domainMax = domain.max;
  const sim::Exchanged e = ranks->exchange(state, settings);
  counts.removed += e.removed;
  engine->uploadState(state);
  if (e.any) engine->shareGrid(e.gridLo, e.gridHi);
}

void Simulation::Impl::refreshGhosts() {
  const sim::GhostDensities ghosts = ranks->ghostDensities(engine->downloadDensities());
  engine->overwriteDensity(ghosts.rows, ghosts.density);
}

void Simulation::distribute(std::shared_ptr<sim::Decomposition> ranks) {
  Impl& s = *impl_;
  if (!ranks) throw std::invalid_argument("distribute: expected a decomposition, got null");
  if (s.clock.steps != 0) throw std::logic_error("distribute: call it before the first step");
  if (s.ranks) throw std::logic_error("distribute: this simulation is divided already");
  const Scene& scene = s.scene;
  const auto refuse = [&](const std::string& what) {
    throw InputError(scene.sourcePath + ": " + what +
                     ": not yet run across processes; run this scene in one process");
  };
  if (scene.fluid.solver == FluidSolver::Pbf) refuse("fluid.solver is \"pbf\"");
  if (!scene.objects.empty()) refuse("the scene has objects");
  if (s.coupling.externalExchange) refuse("an object engine is attached");
  if (!scene.emitters.empty()) refuse("the scene has emitters");
  if (!scene.outlets.empty()) refuse("the scene has outlets");
  if (!scene.probes.empty()) refuse("the scene has probes");
  if (s.params.periodic.axes != 0) refuse("the domain is periodic");
  s.ranks = std::move(ranks);
  s.stages = s.stageList();
  // Divided from frame 0 on: each process keeps its share, with its ghosts and their densities.
  const backend::ScopedThreadCount passThreads(s.threads);
  s.exchangeParticles();
  s.buildGrid();
  s.sumDensity();
  s.refreshGhosts();
}

}  // namespace sph
