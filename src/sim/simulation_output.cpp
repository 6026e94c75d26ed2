// What a Simulation reports: statistics and frames, from a host copy of the particles, made
// on demand at output times.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "backend/cpu_parallel.hpp"
#include "sim/simulation_impl.hpp"
#include "sph/core/eos.hpp"

namespace sph {

namespace {

struct Sums {
  double kineticEnergy = 0.0;
  double density = 0.0;
  double densityError = 0.0;
  float maxDensityError = 0.0f;
  float maxSpeedSquared = 0.0f;
  std::uint64_t surface = 0;
};

struct FrameBuilder {
  ParticleFrame out;
  void reserve(std::size_t n) {
    out.id.reserve(n);
    out.position.reserve(3 * n);
    out.velocity.reserve(3 * n);
    out.density.reserve(n);
    out.pressure.reserve(n);
    out.kind.reserve(n);
    out.object.reserve(n);
    out.surface.reserve(n);
    out.torn.reserve(n);
  }
  void push(std::uint32_t id, Vec4 x, Vec4 v, float rho, float p, ParticleKind kind,
            std::int32_t object = -1, bool surface = false, bool torn = false) {
    out.id.push_back(id);
    out.position.insert(out.position.end(), {x.x, x.y, x.z});
    out.velocity.insert(out.velocity.end(), {v.x, v.y, v.z});
    out.density.push_back(rho);
    out.pressure.push_back(p);
    out.kind.push_back(static_cast<std::uint8_t>(kind));
    out.object.push_back(object);
    out.surface.push_back(surface ? 1 : 0);
    out.torn.push_back(torn ? 1 : 0);
  }
};

// In id order: 0 .. initialFluid-1 with gaps where particles were removed, then those emitters
// put in (their ids after the objects').
void appendFluid(FrameBuilder& b, const sim::HostParticles& f, std::uint64_t initialFluid,
                 float surfaceThreshold) {
  std::uint64_t ids = initialFluid;
  for (std::uint32_t id : f.id) ids = std::max<std::uint64_t>(ids, std::uint64_t(id) + 1);
  std::vector<std::int64_t> slotOfId(ids, -1);
  for (std::size_t i = 0; i < f.id.size(); ++i) slotOfId[f.id[i]] = static_cast<std::int64_t>(i);
  for (std::int64_t slot : slotOfId) {
    if (slot < 0) continue;
    const auto i = static_cast<std::size_t>(slot);
    b.push(f.id[i], f.position[i], f.velocity[i], f.density[i], f.pressure[i], ParticleKind::Fluid,
           -1, f.acceleration[i].w > surfaceThreshold);
  }
}

// Wall ids follow the fluid's.
void appendWalls(FrameBuilder& b, const sim::HostWalls& w, std::uint64_t firstId,
                 float restDensity) {
  std::vector<std::size_t> byId(w.id.size());
  for (std::size_t k = 0; k < w.id.size(); ++k) byId[w.id[k] - firstId] = k;
  for (std::size_t k : byId)
    b.push(w.id[k], w.position[k], Vec4{0, 0, 0, 0}, restDensity, 0.0f, ParticleKind::Boundary);
}

// Object particle ids follow the walls'.
void appendObjects(FrameBuilder& b, const objects::ParticleState& p, std::uint64_t firstId,
                   float restDensity) {
  for (std::size_t k = 0; k < p.size(); ++k) {
    b.push(static_cast<std::uint32_t>(firstId + k), makeVec4(p.position[k]),
           makeVec4(p.velocity[k]), restDensity, 0.0f, ParticleKind::Object, p.object[k],
           p.surface[k] != 0, p.cut[k] != 0);
  }
}

// An attached engine's particles as it last published them, their ids following the walls' by
// handle.
void appendAttached(FrameBuilder& b, const ObjectSurface& s, std::uint64_t firstId,
                    float restDensity) {
  std::vector<std::size_t> byHandle(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) byHandle[k] = k;
  std::sort(byHandle.begin(), byHandle.end(),
            [&](std::size_t a, std::size_t c) { return s.handle[a] < s.handle[c]; });
  for (std::size_t k : byHandle) {
    b.push(static_cast<std::uint32_t>(firstId + s.handle[k]), s.position[k],
           makeVec4(xyz(s.velocity[k]), 0.0f), restDensity, 0.0f, ParticleKind::Object, s.object[k],
           true);
  }
}

// The walls (if asked), then the objects as their engine has them now.
void appendSolids(FrameBuilder& b, const sim::FluidEngine& engine, const sim::ObjectRunner* objects,
                  const ObjectSurface& attached, std::uint64_t initialFluid, float restDensity,
                  bool includeBoundary) {
  if (includeBoundary) appendWalls(b, engine.downloadWalls(), initialFluid, restDensity);
  if (objects) {
    objects->wait();
    appendObjects(b, objects->world().particles(), initialFluid + engine.wallCount(), restDensity);
  }
  appendAttached(b, attached, initialFluid + engine.wallCount(), restDensity);
}

}  // namespace

std::vector<ObjectStats> Simulation::objectStats() const {
  const Impl& s = *impl_;
  std::vector<ObjectStats> out;
  if (s.coupling.externalExchange) {  // what the fluid knows of an attached engine's objects
    for (std::size_t o = 0; o < s.coupling.fluidForceOnObject.size(); ++o) {
      ObjectStats stats;
      // A scene's objects made by Bullet keep their scene names (BulletEngine::forScene).
      const bool named =
          s.scene.objectEngine.type == ObjectEngineKind::Bullet && o < s.scene.objects.size();
      stats.name = named ? s.scene.objects[o].name : "object " + std::to_string(o);
      const Vec3 f = s.coupling.fluidForceOnObject[o];
      stats.fluidForce = {f.x, f.y, f.z};
      out.push_back(stats);
    }
    return out;
  }
  if (!s.coupling.objects) return out;
  s.coupling.objects->wait();
  const objects::ObjectWorld& world = s.coupling.objects->world();
  for (std::size_t o = 0; o < world.objectCount(); ++o) {
    const objects::ObjectInfo info = world.info(o);
    ObjectStats stats;
    stats.name = info.name;
    stats.mass = info.mass;
    stats.centreOfMass = {info.centreOfMass.x, info.centreOfMass.y, info.centreOfMass.z};
    stats.velocity = {info.velocity.x, info.velocity.y, info.velocity.z};
    const Vec3 f = s.coupling.fluidForceOnObject[o];
    stats.fluidForce = {f.x, f.y, f.z};
    stats.contactForce = {info.contactForce.x, info.contactForce.y, info.contactForce.z};
    stats.startCentre = {info.startCentre.x, info.startCentre.y, info.startCentre.z};
    stats.brokenSprings = info.brokenSprings;
    stats.volumeRatio = info.volumeRatio;
    out.push_back(stats);
  }
  return out;
}

std::vector<std::uint32_t> Simulation::leakedIds() const {
  const Impl& s = *impl_;
  std::vector<std::uint32_t> out;
  if (!s.coupling.objects && s.coupling.externalContainers.empty()) return out;
  const sim::HostContainment c = s.engine->downloadContainment();
  for (std::size_t k = 0; k < c.containerById.size(); ++k)
    if (c.containerById[k] >= 0 && c.insideById[k] == 0) out.push_back(std::uint32_t(k));
  return out;
}

std::uint64_t Simulation::leakedCount() const {
  return leakedIds().size();
}

std::vector<float> Simulation::leakPositions() const {
  const Impl& s = *impl_;
  std::vector<float> out;
  if (!s.coupling.objects && s.coupling.externalContainers.empty()) return out;
  const sim::HostContainment c = s.engine->downloadContainment();
  for (std::size_t k = 0; k < c.containerById.size(); ++k) {
    const Vec4 x = c.firstExitById[k];
    if (x.w != 0.0f) out.insert(out.end(), {x.x, x.y, x.z});
  }
  return out;
}

namespace {

// The statistics that the fluid particles' host copy gives.
void addParticleSums(FrameStats& out, const sim::HostParticles& f, float restDensity,
                     float surfaceThreshold, double mass) {
  const Sums sums = backend::reduce(
      f.id.size(), Sums{},
      [&](std::size_t i) {
        const float v2 = lengthSquared(xyz(f.velocity[i]));
        const float error = compression(f.density[i], restDensity);
        return Sums{
            0.5 * mass * v2, f.density[i], error,
            error,           v2,           f.acceleration[i].w > surfaceThreshold ? 1u : 0u};
      },
      [](Sums a, const Sums& b) {
        a.kineticEnergy += b.kineticEnergy;
        a.density += b.density;
        a.densityError += b.densityError;
        a.maxDensityError = std::max(a.maxDensityError, b.maxDensityError);
        a.maxSpeedSquared = std::max(a.maxSpeedSquared, b.maxSpeedSquared);
        a.surface += b.surface;
        return a;
      });
  const std::size_t n = f.id.size();
  out.fluidCount = n;
  out.kineticEnergy = sums.kineticEnergy;
  out.meanDensity = n ? sums.density / double(n) : 0.0;
  out.averageDensityError = n ? sums.densityError / double(n) : 0.0;
  out.maxDensityError = sums.maxDensityError;
  out.maxSpeed = std::sqrt(double(sums.maxSpeedSquared));
  out.surfaceCount = sums.surface;
}

}  // namespace

struct FrameCapture::Impl {
  std::unique_ptr<sim::PendingParticles> fluid;
  FrameStats stats;  // all but what the fluid's copy gives
  std::optional<objects::ParticleState> objects;
  ObjectSurface attached;  // an attached engine's, as last published
  std::uint64_t initialFluid = 0;
  std::uint64_t firstObjectId = 0;
  float restDensity = 0.0f;
  float surfaceThreshold = 0.0f;
  double mass = 0.0;
  bool statsComplete = false;  // a distributed run's, reduced across processes at capture
};

FrameCapture::FrameCapture(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
FrameCapture::FrameCapture(FrameCapture&&) noexcept = default;
FrameCapture& FrameCapture::operator=(FrameCapture&&) noexcept = default;
FrameCapture::~FrameCapture() = default;

void FrameCapture::take(ParticleFrame& frame, FrameStats& stats) {
  Impl& c = *impl_;
  const sim::HostParticles f = c.fluid->take();
  stats = c.stats;
  if (!c.statsComplete) addParticleSums(stats, f, c.restDensity, c.surfaceThreshold, c.mass);
  FrameBuilder b;
  b.out.time = stats.time;
  b.out.step = stats.steps;
  b.reserve(f.id.size() + (c.objects ? c.objects->size() : 0));
  appendFluid(b, f, c.initialFluid, c.surfaceThreshold);
  if (c.objects) appendObjects(b, *c.objects, c.firstObjectId, c.restDensity);
  appendAttached(b, c.attached, c.firstObjectId, c.restDensity);
  frame = std::move(b.out);
}

FrameStats Simulation::Impl::statsWithoutParticles(const Simulation& sim) const {
  FrameStats out;
  out.time = clock.time;
  out.steps = clock.steps;
  out.dt = clock.dt;
  out.boundaryCount = engine->wallCount();
  out.leakedCount = sim.leakedCount();
  out.removedCount = counts.removed;
  out.emittedCount = sim.emittedCount();
  out.clampedCount = counts.clamped;
  out.contactPairs = coupling.contactPairs;
  out.densityIterations = solves.densityIterations;
  out.divergenceIterations = solves.divergenceIterations;
  out.unconvergedSolves = solves.unconvergedSolves;
  out.objects = sim.objectStats();
  return out;
}

sim::HostParticles Simulation::Impl::ownedParticles() const {
  sim::HostParticles f = engine->download();
  if (!ranks) return f;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < f.id.size(); ++i) {
    if (fluid::isGhost(f.id[i])) continue;
    f.id[kept] = f.id[i];
    f.position[kept] = f.position[i];
    f.velocity[kept] = f.velocity[i];
    f.density[kept] = f.density[i];
    f.pressure[kept] = f.pressure[i];
    f.acceleration[kept] = f.acceleration[i];
    ++kept;
  }
  for (auto* a : {&f.position, &f.velocity, &f.acceleration}) a->resize(kept);
  for (auto* a : {&f.density, &f.pressure}) a->resize(kept);
  f.id.resize(kept);
  return f;
}

void Simulation::Impl::addAcrossProcesses(FrameStats& out) const {
  sim::Decomposition& all = *ranks;
  const double n = double(out.fluidCount);
  out.fluidCount = all.sum(out.fluidCount);
  const double total = double(out.fluidCount);
  out.kineticEnergy = all.sum(out.kineticEnergy);
  out.meanDensity = total > 0 ? all.sum(out.meanDensity * n) / total : 0.0;
  out.averageDensityError = total > 0 ? all.sum(out.averageDensityError * n) / total : 0.0;
  out.maxDensityError = all.max(out.maxDensityError);
  out.maxSpeed = all.max(out.maxSpeed);
  out.surfaceCount = all.sum(out.surfaceCount);
  out.clampedCount = all.sum(out.clampedCount);
}

FrameStats Simulation::stats() const {
  const Impl& s = *impl_;
  FrameStats out = s.statsWithoutParticles(*this);
  s.measureSurfaceIfStale();
  addParticleSums(out, s.ownedParticles(), s.params.restDensity, s.params.surfaceThreshold,
                  s.params.mass);
  if (s.ranks) s.addAcrossProcesses(out);
  return out;
}

FrameCapture Simulation::capture() const {
  const Impl& s = *impl_;
  auto c = std::make_unique<FrameCapture::Impl>();
  s.measureSurfaceIfStale();
  c->stats = s.statsWithoutParticles(*this);
  if (s.ranks) {
    // The statistics are every process's: reduced now, on the thread that steps.
    sim::HostParticles owned = s.ownedParticles();
    addParticleSums(c->stats, owned, s.params.restDensity, s.params.surfaceThreshold,
                    s.params.mass);
    s.addAcrossProcesses(c->stats);
    c->statsComplete = true;
    c->fluid = std::make_unique<sim::ReadyParticles>(std::move(owned));
  } else {
    c->fluid = s.engine->beginDownload();
  }
  if (s.coupling.objects) {
    s.coupling.objects->wait();
    c->objects = s.coupling.objects->world().particles();
  }
  c->attached = s.coupling.externalSurface;
  c->initialFluid = s.counts.initialFluid;
  c->firstObjectId = s.counts.initialFluid + s.engine->wallCount();
  c->restDensity = s.params.restDensity;
  c->surfaceThreshold = s.params.surfaceThreshold;
  c->mass = s.params.mass;
  return FrameCapture(std::move(c));
}

ParticleFrame Simulation::frame(bool includeBoundary) const {
  const Impl& s = *impl_;
  s.measureSurfaceIfStale();
  const sim::HostParticles f = s.ownedParticles();
  FrameBuilder b;
  b.out.time = s.clock.time;
  b.out.step = s.clock.steps;
  b.reserve(f.id.size() + (includeBoundary ? s.engine->wallCount() : 0) +
            s.calibration.objectParticles);
  appendFluid(b, f, s.counts.initialFluid, s.params.surfaceThreshold);
  appendSolids(b, *s.engine, s.coupling.objects.get(), s.coupling.externalSurface,
               s.counts.initialFluid, s.params.restDensity, includeBoundary);
  return std::move(b.out);
}

FluidView Simulation::fluidView() const {
  FluidView v = impl_->engine->hostView();
  v.step = impl_->clock.steps;
  return v;
}

ParticleFrame Simulation::solidFrame(bool includeBoundary) const {
  const Impl& s = *impl_;
  FrameBuilder b;
  b.out.time = s.clock.time;
  b.out.step = s.clock.steps;
  b.reserve((includeBoundary ? s.engine->wallCount() : 0) + s.calibration.objectParticles);
  appendSolids(b, *s.engine, s.coupling.objects.get(), s.coupling.externalSurface,
               s.counts.initialFluid, s.params.restDensity, includeBoundary);
  return std::move(b.out);
}

std::size_t Simulation::writeFluidForDrawing(const FluidDrawTarget& target) const {
  const Impl& s = *impl_;
  const std::size_t n = s.engine->fluidCount();
  if (target.capacity < n)
    throw std::invalid_argument("writeFluidForDrawing: room for " +
                                std::to_string(target.capacity) + " particles, the fluid has " +
                                std::to_string(n));
  if (!target.position) throw std::invalid_argument("writeFluidForDrawing: no position array");
  if (reinterpret_cast<std::uintptr_t>(target.position) % alignof(Vec4) != 0)
    throw std::invalid_argument("writeFluidForDrawing: positions must be 16-byte aligned");
  if (target.quantity != FluidQuantity::None && !target.value)
    throw std::invalid_argument(
        "writeFluidForDrawing: a quantity was asked for and no value array given");
  if (target.quantity == FluidQuantity::Surface) s.measureSurfaceIfStale();
  s.engine->writeForDrawing(target, s.params.surfaceThreshold);
  return n;
}

ParticleFrame Simulation::boundaryFrame() const {
  const Impl& s = *impl_;
  FrameBuilder b;
  b.out.time = s.clock.time;
  b.out.step = s.clock.steps;
  b.reserve(s.engine->wallCount());
  appendWalls(b, s.engine->downloadWalls(), s.counts.initialFluid, s.params.restDensity);
  return std::move(b.out);
}

}  // namespace sph
