// A simulation's whole state as bytes, and back: what checkpoints and resumed runs are made of.
// What is saved is what the next step reads — the particles in the engine's order, the clock and
// the adaptive step, the counters, the incompressible solver's warm start, the emitters', the
// probes' and the outlets' progress, the live parameters, the objects' engine and its exchange
// with the fluid — so that a simulation built from the same scene and given the state steps on
// exactly as the one that saved it. Each part is read whole and checked before any is applied.
#include <sstream>
#include <stdexcept>
#include <string>

#include "sim/simulation_impl.hpp"
#include "sim/state_parts.hpp"

namespace sph {

using sim::Counters;
using sim::Fingerprint;
using sim::ObjectsState;

void Simulation::saveState(std::ostream& out) const {
  const Impl& s = *impl_;
  if (s.externalExchange)
    throw std::logic_error(
        "saveState: an attached object engine's objects are its own state, not the "
        "simulation's: a saved state could not put them back");
  sim::StateWriter w;
  sim::fingerprintOf(s.scene, s.initialFluid, s.engine->wallCount(), s.calibration.objectParticles)
      .write(w);
  Counters{s.time,
           s.dt,
           s.movedFor,
           s.steps,
           s.removed,
           s.clamped,
           s.nextId,
           s.divergenceReport,
           s.densityReport,
           s.solverTotals.densityIterations,
           s.solverTotals.divergenceIterations,
           s.solverTotals.unconvergedSolves}
      .write(w);
  sim::writeLive(w, liveParameters());
  w.vector(s.fluidForceOnWall);
  s.emitters.save(w);
  s.probes->save(w);
  s.measureSurfaceIfStale();  // the flags travel with the state: no neighbours come with it
  sim::writeFluid(w, s.engine->downloadState());
  w.value(std::uint8_t(s.objects ? 1 : 0));
  if (s.objects) {
    s.objects->wait();  // the engine's step handed over at the end of the last fluid step
    ObjectsState{
        s.objects->world().state(), s.objects->pacing(),    s.objects->exchange().snapshot(),
        s.seenPublication,          s.objectMaxSpeed,       s.contactPairs,
        s.fluidForceOnObject,       s.contactForceOnObject, s.engine->downloadContainment()}
        .write(w);
  }
  w.finish(out);
}

void Simulation::loadState(std::istream& in) {
  Impl& s = *impl_;
  sim::StateReader r(in);  // the whole state read and its checksum checked
  const Fingerprint f = Fingerprint::read(r);
  if (f.initialFluid != s.initialFluid)
    r.mismatch("it starts with " + std::to_string(f.initialFluid) +
               " fluid particles, this scene with " + std::to_string(s.initialFluid));
  if (f.walls != s.engine->wallCount())
    r.mismatch("it has " + std::to_string(f.walls) + " wall particles, this scene " +
               std::to_string(s.engine->wallCount()));
  if (f.objectParticles != s.calibration.objectParticles) r.mismatch("its object particles");
  if (f.solver != std::uint64_t(s.scene.fluid.solver)) r.mismatch("its fluid.solver");
  if (f.emitters != s.scene.emitters.size() || f.outlets != s.scene.outlets.size() ||
      f.probes != s.scene.probes.size())
    r.mismatch("its emitters, outlets or probes");
  if (f.spacing != s.scene.fluid.spacing) r.mismatch("its fluid.spacing");

  // Every part read into copies and checked first: a state refused half way changes nothing.
  const Counters counters = Counters::read(r);
  const LiveParameters live = sim::readLive(r);
  std::vector<Vec3> fluidForceOnWall = r.vector<Vec3>();
  if (fluidForceOnWall.size() != s.fluidForceOnWall.size()) r.mismatch("its force probes");
  sim::Emitters emitters = s.emitters;
  emitters.load(r);
  sim::ProbeSampler probes = *s.probes;
  probes.load(r);
  const sim::HostFluidState fluid = sim::readFluid(r, counters.nextId, s.scene.outlets.size());
  const bool hasObjects = r.value<std::uint8_t>() != 0;
  if (hasObjects != bool(s.objects)) r.mismatch("its objects");
  ObjectsState objects;
  if (hasObjects)
    objects = ObjectsState::read(r, s.objects->exchange().handleCount(),
                                 s.fluidForceOnObject.size(), s.initialFluid);
  r.expectEnd();
  if (hasObjects) {
    s.objects->wait();
    try {  // first: the world checks its own sizes before it changes anything
      s.objects->world().restore(objects.world);
    } catch (const std::invalid_argument& e) {
      r.mismatch(e.what());
    }
  }

  if (!sim::sameLive(live, liveParameters())) setLiveParameters(live);
  const backend::ScopedThreadCount passThreads(s.threads);
  s.engine->uploadState(fluid);
  s.time = counters.time;
  s.dt = counters.dt;
  s.movedFor = counters.movedFor;
  s.steps = counters.steps;
  s.removed = counters.removed;
  s.clamped = counters.clamped;
  s.nextId = counters.nextId;
  s.divergenceReport = counters.divergence;
  s.densityReport = counters.density;
  s.solverTotals.densityIterations = counters.densityIterations;
  s.solverTotals.divergenceIterations = counters.divergenceIterations;
  s.solverTotals.unconvergedSolves = counters.unconvergedSolves;
  s.neighboursListed = false;  // no density pass has listed these particles' neighbours
  s.surfaceMeasured = true;    // the flags came with the state
  s.fluidForceOnWall = std::move(fluidForceOnWall);
  s.emitters = std::move(emitters);
  *s.probes = std::move(probes);
  if (!hasObjects) return;
  s.objects->setPacing(objects.pacing);
  const std::uint64_t published = objects.exchange.version;
  s.objects->exchange().restore(std::move(objects.exchange));
  s.engine->uploadContainment(objects.containment);
  s.seenPublication = objects.seenPublication;
  // The fluid keeps its own copy of the publication it read last: made again here when that is
  // the newest. A newer one (the engine's step since) is read at the next step, as it would
  // have been, before anything uses the fluid's copy.
  if (published == objects.seenPublication) {
    std::uint64_t older = published - 1;
    s.objects->exchange().readIfNew(older, [&](const ObjectSurface& surface) {
      s.engine->setObjectSurface(surface, s.interactionParams);
    });
  }
  s.objectMaxSpeed = objects.objectMaxSpeed;
  s.contactPairs = objects.contactPairs;
  s.fluidForceOnObject = std::move(objects.fluidForceOnObject);
  s.contactForceOnObject = std::move(objects.contactForceOnObject);
}
}  // namespace sph
