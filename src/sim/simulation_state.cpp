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
  if (s.coupling.externalExchange)
    throw std::logic_error(
        "saveState: an attached object engine's objects are its own state, not the "
        "simulation's: a saved state could not put them back");
  if (s.ranks)
    throw std::logic_error(
        "saveState: a run across processes is not yet saved (each process "
        "holds its part and copies of its neighbours')");
  sim::StateWriter w;
  sim::fingerprintOf(s.scene, s.counts.initialFluid, s.engine->wallCount(),
                     s.calibration.objectParticles)
      .write(w);
  Counters{s.clock.time,
           s.clock.dt,
           s.clock.movedFor,
           s.clock.steps,
           s.counts.removed,
           s.counts.clamped,
           s.inflow.nextId,
           s.solves.divergence,
           s.solves.density,
           s.solves.densityIterations,
           s.solves.divergenceIterations,
           s.solves.unconvergedSolves}
      .write(w);
  sim::writeLive(w, liveParameters());
  w.vector(s.outputs.fluidForceOnWall);
  s.inflow.emitters.save(w);
  s.outputs.probes->save(w);
  s.measureSurfaceIfStale();  // the flags travel with the state: no neighbours come with it
  sim::writeFluid(w, s.engine->downloadState());
  const sim::ObjectCoupling& c = s.coupling;
  w.value(std::uint8_t(c.objects ? 1 : 0));
  if (c.objects) {
    c.objects->wait();  // the engine's step handed over at the end of the last fluid step
    ObjectsState{
        c.objects->world().state(), c.objects->pacing(),    c.objects->exchange().snapshot(),
        c.seenPublication,          c.objectMaxSpeed,       c.contactPairs,
        c.fluidForceOnObject,       c.contactForceOnObject, s.engine->downloadContainment()}
        .write(w);
  }
  w.finish(out);
}

void Simulation::loadState(std::istream& in) {
  Impl& s = *impl_;
  sim::StateReader r(in);  // the whole state read and its checksum checked
  const Fingerprint f = Fingerprint::read(r);
  if (f.initialFluid != s.counts.initialFluid)
    r.mismatch("it starts with " + std::to_string(f.initialFluid) +
               " fluid particles, this scene with " + std::to_string(s.counts.initialFluid));
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
  if (fluidForceOnWall.size() != s.outputs.fluidForceOnWall.size()) r.mismatch("its force probes");
  sim::Emitters emitters = s.inflow.emitters;
  emitters.load(r);
  sim::ProbeSampler probes = *s.outputs.probes;
  probes.load(r);
  const sim::HostFluidState fluid = sim::readFluid(r, counters.nextId, s.scene.outlets.size());
  const bool hasObjects = r.value<std::uint8_t>() != 0;
  sim::ObjectCoupling& c = s.coupling;
  if (hasObjects != bool(c.objects)) r.mismatch("its objects");
  ObjectsState objects;
  if (hasObjects)
    objects = ObjectsState::read(r, c.objects->exchange().handleCount(),
                                 c.fluidForceOnObject.size(), s.counts.initialFluid);
  r.expectEnd();
  if (hasObjects) {
    c.objects->wait();
    try {  // first: the world checks its own sizes before it changes anything
      c.objects->world().restore(objects.world);
    } catch (const std::invalid_argument& e) {
      r.mismatch(e.what());
    }
  }

  if (!sim::sameLive(live, liveParameters())) setLiveParameters(live);
  const backend::ScopedThreadCount passThreads(s.threads);
  s.engine->uploadState(fluid);
  s.clock.time = counters.time;
  s.clock.dt = counters.dt;
  s.clock.movedFor = counters.movedFor;
  s.clock.steps = counters.steps;
  s.counts.removed = counters.removed;
  s.counts.clamped = counters.clamped;
  s.inflow.nextId = counters.nextId;
  s.solves.divergence = counters.divergence;
  s.solves.density = counters.density;
  s.solves.densityIterations = counters.densityIterations;
  s.solves.divergenceIterations = counters.divergenceIterations;
  s.solves.unconvergedSolves = counters.unconvergedSolves;
  s.outputs.neighboursListed = false;  // no density pass has listed these particles' neighbours
  s.outputs.surfaceMeasured = true;    // the flags came with the state
  s.outputs.fluidForceOnWall = std::move(fluidForceOnWall);
  s.inflow.emitters = std::move(emitters);
  *s.outputs.probes = std::move(probes);
  if (!hasObjects) return;
  c.objects->setPacing(objects.pacing);
  const std::uint64_t published = objects.exchange.version;
  c.objects->exchange().restore(std::move(objects.exchange));
  s.engine->uploadContainment(objects.containment);
  c.seenPublication = objects.seenPublication;
  // The fluid keeps its own copy of the publication it read last: made again here when that is
  // the newest. A newer one (the engine's step since) is read at the next step, as it would
  // have been, before anything uses the fluid's copy.
  if (published == objects.seenPublication) {
    std::uint64_t older = published - 1;
    c.objects->exchange().readIfNew(older, [&](const ObjectSurface& surface) {
      s.engine->setObjectSurface(surface, c.params);
    });
  }
  c.objectMaxSpeed = objects.objectMaxSpeed;
  c.contactPairs = objects.contactPairs;
  c.fluidForceOnObject = std::move(objects.fluidForceOnObject);
  c.contactForceOnObject = std::move(objects.contactForceOnObject);
}
}  // namespace sph
