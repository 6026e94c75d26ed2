// A simulation's whole state as bytes, and back: what checkpoints and resumed runs are made of.
// What is saved is what the next step reads — the particles in the engine's order, the clock and
// the adaptive step, the counters, the incompressible solver's warm start, the emitters', the
// probes' and the outlets' progress, the live parameters — so that a simulation built from the
// same scene and given the state steps on exactly as the one that saved it.
#include <sstream>
#include <string>

#include "sim/simulation_impl.hpp"
#include "sim/state_stream.hpp"

namespace sph {

namespace {

void writeLive(sim::StateWriter& out, const LiveParameters& p) {
  out.value(p.viscosity);
  out.value(p.stiffness);
  out.value(p.gravity);
  out.value(p.surfaceTension);
  out.value(p.influenceRatio);
}

LiveParameters readLive(sim::StateReader& in) {
  LiveParameters p;
  p.viscosity = in.value<double>();
  p.stiffness = in.value<double>();
  p.gravity = in.value<Vec3d>();
  p.surfaceTension = in.value<double>();
  p.influenceRatio = in.value<double>();
  return p;
}

bool sameLive(const LiveParameters& a, const LiveParameters& b) {
  return a.viscosity == b.viscosity && a.stiffness == b.stiffness && a.gravity == b.gravity &&
         a.surfaceTension == b.surfaceTension && a.influenceRatio == b.influenceRatio;
}

void writeReport(sim::StateWriter& out, const fluid::SolverReport& r) {
  out.value(r.iterations);
  out.value(r.averageError);
  out.value(r.largestError);
  out.value(r.converged);
}

fluid::SolverReport readReport(sim::StateReader& in) {
  fluid::SolverReport r;
  r.iterations = in.value<int>();
  r.averageError = in.value<float>();
  r.largestError = in.value<float>();
  r.converged = in.value<bool>();
  return r;
}

// What fixes the layout of the rest: a state saved from another scene stops here.
struct Fingerprint {
  std::uint64_t initialFluid = 0, walls = 0, objectParticles = 0;
  std::uint64_t solver = 0, emitters = 0, outlets = 0, probes = 0;
  double spacing = 0.0;

  void write(sim::StateWriter& out) const {
    for (std::uint64_t v :
         {initialFluid, walls, objectParticles, solver, emitters, outlets, probes})
      out.value(v);
    out.value(spacing);
  }
  static Fingerprint read(sim::StateReader& in) {
    Fingerprint f;
    for (std::uint64_t* v : {&f.initialFluid, &f.walls, &f.objectParticles, &f.solver, &f.emitters,
                             &f.outlets, &f.probes})
      *v = in.value<std::uint64_t>();
    f.spacing = in.value<double>();
    return f;
  }
};

Fingerprint fingerprintOf(const Scene& scene, std::uint64_t initialFluid, std::uint64_t walls,
                          std::uint64_t objectParticles) {
  Fingerprint f;
  f.initialFluid = initialFluid;
  f.walls = walls;
  f.objectParticles = objectParticles;
  f.solver = std::uint64_t(scene.fluid.solver);
  f.emitters = scene.emitters.size();
  f.outlets = scene.outlets.size();
  f.probes = scene.probes.size();
  f.spacing = scene.fluid.spacing;
  return f;
}

void writeSurface(sim::StateWriter& out, const ObjectSurface& s) {
  out.vector(s.position);
  out.vector(s.velocity);
  out.vector(s.normal);
  out.vector(s.handle);
  out.vector(s.object);
  out.vector(s.cut);
  out.value(s.time);
}

ObjectSurface readSurface(sim::StateReader& in) {
  ObjectSurface s;
  s.position = in.vector<Vec4>();
  s.velocity = in.vector<Vec4>();
  s.normal = in.vector<Vec4>();
  s.handle = in.vector<std::uint32_t>();
  s.object = in.vector<std::int32_t>();
  s.cut = in.vector<std::uint8_t>();
  s.time = in.value<double>();
  const std::size_t n = s.handle.size();
  for (std::size_t size : {s.position.size(), s.velocity.size(), s.normal.size(), s.object.size(),
                           s.cut.size()})
    if (size != n) in.mismatch("its objects' surface lists differ in length");
  return s;
}

void writeWorld(sim::StateWriter& out, const objects::WorldState& w) {
  out.value(w.time);
  out.vector(w.position);
  out.vector(w.velocity);
  out.vector(w.contactForce);
  out.vector(w.cut);
  out.vector(w.bodies);
  out.vector(w.springBroken);
  out.vector(w.bendingBroken);
  out.vector(w.pathKeyCounts);
  out.vector(w.pathKeys);
}

objects::WorldState readWorld(sim::StateReader& in) {
  objects::WorldState w;
  w.time = in.value<double>();
  w.position = in.vector<double>();
  w.velocity = in.vector<double>();
  w.contactForce = in.vector<double>();
  w.cut = in.vector<std::uint8_t>();
  w.bodies = in.vector<double>();
  w.springBroken = in.vector<std::uint8_t>();
  w.bendingBroken = in.vector<std::uint8_t>();
  w.pathKeyCounts = in.vector<std::uint64_t>();
  w.pathKeys = in.vector<KeyframeDesc>();
  return w;
}

// The objects' part of a state: the engine's world, its pacing and the exchange between it and
// the fluid, and what the fluid keeps of them.
struct ObjectsState {
  objects::WorldState world;
  sim::ObjectRunner::Pacing pacing;
  ObjectExchange::Snapshot exchange;
  std::uint64_t seenPublication = 0;
  float objectMaxSpeed = 0.0f;
  std::uint64_t contactPairs = 0;
  std::vector<Vec3> fluidForceOnObject, contactForceOnObject;
  sim::HostContainment containment;
};

}  // namespace

void Simulation::saveState(std::ostream& out) const {
  const Impl& s = *impl_;
  sim::StateWriter w;
  fingerprintOf(s.scene, s.initialFluid, s.engine->wallCount(), s.calibration.objectParticles)
      .write(w);
  w.value(s.time);
  w.value(s.dt);
  w.value(s.steps);
  w.value(s.removed);
  w.value(s.clamped);
  w.value(s.movedFor);
  w.value(s.nextId);
  writeReport(w, s.divergenceReport);
  writeReport(w, s.densityReport);
  w.value(s.solverTotals.densityIterations);
  w.value(s.solverTotals.divergenceIterations);
  w.value(s.solverTotals.unconvergedSolves);
  writeLive(w, liveParameters());
  w.vector(s.fluidForceOnWall);
  s.emitters.save(w);
  s.probes->save(w);

  s.measureSurfaceIfStale();  // the flags travel with the state: no neighbours come with it
  const sim::HostFluidState fluid = s.engine->downloadState();
  w.vector(fluid.id);
  w.vector(fluid.position);
  w.vector(fluid.velocity);
  w.vector(fluid.acceleration);
  w.vector(fluid.density);
  w.vector(fluid.pressure);
  w.vector(fluid.warmStart);
  w.vector(fluid.externalById);
  w.vector(fluid.drainedByOutlet);
  w.value(fluid.densityIsState);

  w.value(std::uint8_t(s.objects ? 1 : 0));
  if (s.objects) {
    s.objects->wait();  // the engine's step handed over at the end of the last fluid step
    writeWorld(w, s.objects->world().state());
    const sim::ObjectRunner::Pacing pacing = s.objects->pacing();
    w.value(pacing.credit);
    w.value(pacing.pendingTime);
    const ObjectExchange::Snapshot exchange = s.objects->exchange().snapshot();
    writeSurface(w, exchange.front);
    w.value(exchange.version);
    w.vector(exchange.impulse);
    w.value(exchange.span);
    w.vector(exchange.lastMean);
    w.value(s.seenPublication);
    w.value(s.objectMaxSpeed);
    w.value(s.contactPairs);
    w.vector(s.fluidForceOnObject);
    w.vector(s.contactForceOnObject);
    const sim::HostContainment containment = s.engine->downloadContainment();
    w.vector(containment.containerById);
    w.vector(containment.insideById);
    w.vector(containment.firstExitById);
  }
  w.finish(out);
}

void Simulation::loadState(std::istream& in) {
  Impl& s = *impl_;
  sim::StateReader r(in);  // the whole state read and checked before anything changes
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

  // Read into copies first: a state that fails half way leaves this simulation as it was.
  const double time = r.value<double>();
  const double dt = r.value<double>();
  const auto steps = r.value<std::uint64_t>();
  const auto removed = r.value<std::uint64_t>();
  const auto clamped = r.value<std::uint64_t>();
  const double movedFor = r.value<double>();
  const auto nextId = r.value<std::uint32_t>();
  const fluid::SolverReport divergence = readReport(r), density = readReport(r);
  const auto densityIterations = r.value<std::uint64_t>();
  const auto divergenceIterations = r.value<std::uint64_t>();
  const auto unconverged = r.value<std::uint64_t>();
  const LiveParameters live = readLive(r);
  std::vector<Vec3> fluidForceOnWall = r.vector<Vec3>();
  if (fluidForceOnWall.size() != s.fluidForceOnWall.size()) r.mismatch("its force probes");
  sim::Emitters emitters = s.emitters;
  emitters.load(r);
  sim::ProbeSampler probes = *s.probes;
  probes.load(r);

  sim::HostFluidState fluid;
  fluid.id = r.vector<std::uint32_t>();
  fluid.position = r.vector<Vec4>();
  fluid.velocity = r.vector<Vec4>();
  fluid.acceleration = r.vector<Vec4>();
  fluid.density = r.vector<float>();
  fluid.pressure = r.vector<float>();
  fluid.warmStart = r.vector<Vec4>();
  fluid.externalById = r.vector<Vec4>();
  fluid.drainedByOutlet = r.vector<std::uint64_t>();
  fluid.densityIsState = r.value<bool>();

  const bool hasObjects = r.value<std::uint8_t>() != 0;
  if (hasObjects != bool(s.objects)) r.mismatch("its objects");
  ObjectsState objects;
  if (hasObjects) {
    objects.world = readWorld(r);
    objects.pacing.credit = r.value<double>();
    objects.pacing.pendingTime = r.value<double>();
    objects.exchange.front = readSurface(r);
    objects.exchange.version = r.value<std::uint64_t>();
    objects.exchange.impulse = r.vector<Vec3>();
    objects.exchange.span = r.value<double>();
    objects.exchange.lastMean = r.vector<Vec3>();
    objects.seenPublication = r.value<std::uint64_t>();
    objects.objectMaxSpeed = r.value<float>();
    objects.contactPairs = r.value<std::uint64_t>();
    objects.fluidForceOnObject = r.vector<Vec3>();
    objects.contactForceOnObject = r.vector<Vec3>();
    objects.containment.containerById = r.vector<std::int32_t>();
    objects.containment.insideById = r.vector<std::uint32_t>();
    objects.containment.firstExitById = r.vector<Vec4>();
    const std::size_t handles = s.objects->exchange().handleCount();
    if (objects.exchange.impulse.size() != handles || objects.exchange.lastMean.size() != handles)
      r.mismatch("its object particles' forces");
    for (std::uint32_t h : objects.exchange.front.handle)
      if (h >= handles) r.mismatch("an object particle past the engine's");
    if (objects.fluidForceOnObject.size() != s.fluidForceOnObject.size() ||
        objects.contactForceOnObject.size() != s.contactForceOnObject.size())
      r.mismatch("its objects' forces");
    const std::size_t ids = objects.containment.containerById.size();
    if (objects.containment.insideById.size() != ids ||
        objects.containment.firstExitById.size() != ids || ids < s.initialFluid)
      r.mismatch("its leak tracking");
  }
  r.expectEnd();
  const std::size_t n = fluid.id.size();
  for (std::size_t size : {fluid.position.size(), fluid.velocity.size(), fluid.acceleration.size(),
                           fluid.density.size(), fluid.pressure.size()})
    if (size != n) r.mismatch("its particle arrays differ in length");
  if (!fluid.warmStart.empty() && fluid.warmStart.size() != n) r.mismatch("its warm start");
  if (fluid.drainedByOutlet.size() != s.scene.outlets.size()) r.mismatch("its outlets");
  for (std::uint32_t id : fluid.id)
    if (id >= nextId) r.mismatch("a particle id past the ids given out");

  if (hasObjects) {
    s.objects->wait();
    try {  // first: the world checks its own sizes before it changes anything
      s.objects->world().restore(objects.world);
    } catch (const std::invalid_argument& e) {
      r.mismatch(e.what());
    }
  }
  if (!sameLive(live, liveParameters())) setLiveParameters(live);
  const backend::ScopedThreadCount passThreads(s.threads);
  s.engine->uploadState(fluid);
  s.time = time;
  s.dt = dt;
  s.steps = steps;
  s.removed = removed;
  s.clamped = clamped;
  s.movedFor = movedFor;
  s.nextId = nextId;
  s.neighboursListed = false;  // no density pass has listed these particles' neighbours
  s.surfaceMeasured = true;    // the flags came with the state
  s.divergenceReport = divergence;
  s.densityReport = density;
  s.solverTotals.densityIterations = densityIterations;
  s.solverTotals.divergenceIterations = divergenceIterations;
  s.solverTotals.unconvergedSolves = unconverged;
  s.fluidForceOnWall = std::move(fluidForceOnWall);
  s.emitters = std::move(emitters);
  *s.probes = std::move(probes);
  if (hasObjects) {
    s.objects->setPacing(objects.pacing);
    s.objects->exchange().restore(std::move(objects.exchange));
    s.engine->uploadContainment(objects.containment);
    s.seenPublication = objects.seenPublication;
    // The fluid keeps its own copy of the publication it read last: made again here when it is
    // the newest. A newer one (the engine's step since) is read at the next step, as it would
    // have been, before anything uses the fluid's copy.
    if (objects.exchange.version == objects.seenPublication) {
      std::uint64_t older = objects.seenPublication - 1;
      s.objects->exchange().readIfNew(older, [&](const ObjectSurface& surface) {
        s.engine->setObjectSurface(surface, s.interactionParams);
      });
    }
    s.objectMaxSpeed = objects.objectMaxSpeed;
    s.contactPairs = objects.contactPairs;
    s.fluidForceOnObject = std::move(objects.fluidForceOnObject);
    s.contactForceOnObject = std::move(objects.contactForceOnObject);
  }
}

}  // namespace sph
