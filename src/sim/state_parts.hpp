// The parts of a saved simulation state (Simulation::saveState), each written and read whole,
// and checked as it is read: what a state saved from another scene, or damaged, is refused by.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fluid/dfsph_settings.hpp"
#include "objects/object_world.hpp"
#include "sim/fluid_engine.hpp"
#include "sim/object_runner.hpp"
#include "sim/state_stream.hpp"
#include "sph/live_parameters.hpp"
#include "sph/object_exchange.hpp"
#include "sph/scene.hpp"

namespace sph::sim {

inline void writeLive(StateWriter& out, const LiveParameters& p) {
  out.value(p.viscosity);
  out.value(p.stiffness);
  out.value(p.gravity);
  out.value(p.surfaceTension);
  out.value(p.influenceRatio);
}

inline LiveParameters readLive(StateReader& in) {
  LiveParameters p;
  p.viscosity = in.value<double>();
  p.stiffness = in.value<double>();
  p.gravity = in.value<Vec3d>();
  p.surfaceTension = in.value<double>();
  p.influenceRatio = in.value<double>();
  return p;
}

inline bool sameLive(const LiveParameters& a, const LiveParameters& b) {
  return a.viscosity == b.viscosity && a.stiffness == b.stiffness && a.gravity == b.gravity &&
         a.surfaceTension == b.surfaceTension && a.influenceRatio == b.influenceRatio;
}

inline void writeReport(StateWriter& out, const fluid::SolverReport& r) {
  out.value(r.iterations);
  out.value(r.averageError);
  out.value(r.largestError);
  out.value(r.converged);
}

inline fluid::SolverReport readReport(StateReader& in) {
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

  void write(StateWriter& out) const {
    for (std::uint64_t v :
         {initialFluid, walls, objectParticles, solver, emitters, outlets, probes})
      out.value(v);
    out.value(spacing);
  }
  static Fingerprint read(StateReader& in) {
    Fingerprint f;
    for (std::uint64_t* v : {&f.initialFluid, &f.walls, &f.objectParticles, &f.solver, &f.emitters,
                             &f.outlets, &f.probes})
      *v = in.value<std::uint64_t>();
    f.spacing = in.value<double>();
    return f;
  }
};

inline Fingerprint fingerprintOf(const Scene& scene, std::uint64_t initialFluid,
                                 std::uint64_t walls, std::uint64_t objectParticles) {
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

inline void writeSurface(StateWriter& out, const ObjectSurface& s) {
  out.vector(s.position);
  out.vector(s.velocity);
  out.vector(s.normal);
  out.vector(s.handle);
  out.vector(s.object);
  out.vector(s.cut);
  out.value(s.time);
}

inline ObjectSurface readSurface(StateReader& in) {
  ObjectSurface s;
  s.position = in.vector<Vec4>();
  s.velocity = in.vector<Vec4>();
  s.normal = in.vector<Vec4>();
  s.handle = in.vector<std::uint32_t>();
  s.object = in.vector<std::int32_t>();
  s.cut = in.vector<std::uint8_t>();
  s.time = in.value<double>();
  const std::size_t n = s.handle.size();
  for (std::size_t size :
       {s.position.size(), s.velocity.size(), s.normal.size(), s.object.size(), s.cut.size()})
    if (size != n) in.mismatch("its objects' surface lists differ in length");
  return s;
}

inline void writeWorld(StateWriter& out, const objects::WorldState& w) {
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

inline objects::WorldState readWorld(StateReader& in) {
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

// The clock, the adaptive step and the counts since the start.
struct Counters {
  double time = 0.0, dt = 0.0, movedFor = 0.0;
  std::uint64_t steps = 0, removed = 0, clamped = 0;
  std::uint32_t nextId = 0;
  fluid::SolverReport divergence, density;
  std::uint64_t densityIterations = 0, divergenceIterations = 0, unconvergedSolves = 0;

  void write(StateWriter& out) const {
    for (double v : {time, dt, movedFor}) out.value(v);
    for (std::uint64_t v : {steps, removed, clamped}) out.value(v);
    out.value(nextId);
    writeReport(out, divergence);
    writeReport(out, density);
    for (std::uint64_t v : {densityIterations, divergenceIterations, unconvergedSolves})
      out.value(v);
  }
  static Counters read(StateReader& in) {
    Counters c;
    for (double* v : {&c.time, &c.dt, &c.movedFor}) *v = in.value<double>();
    for (std::uint64_t* v : {&c.steps, &c.removed, &c.clamped}) *v = in.value<std::uint64_t>();
    c.nextId = in.value<std::uint32_t>();
    c.divergence = readReport(in);
    c.density = readReport(in);
    for (std::uint64_t* v : {&c.densityIterations, &c.divergenceIterations, &c.unconvergedSolves})
      *v = in.value<std::uint64_t>();
    return c;
  }
};

inline void writeFluid(StateWriter& out, const HostFluidState& fluid) {
  const HostParticles& p = fluid.particles;
  out.vector(p.id);
  out.vector(p.position);
  out.vector(p.velocity);
  out.vector(p.acceleration);
  out.vector(p.density);
  out.vector(p.pressure);
  out.vector(fluid.warmStart);
  out.vector(fluid.externalById);
  out.vector(fluid.drainedByOutlet);
  out.value(fluid.densityIsState);
}

// Checked against the ids given out and the scene's outlets.
inline HostFluidState readFluid(StateReader& in, std::uint32_t nextId, std::size_t outlets) {
  HostFluidState fluid;
  HostParticles& p = fluid.particles;
  p.id = in.vector<std::uint32_t>();
  p.position = in.vector<Vec4>();
  p.velocity = in.vector<Vec4>();
  p.acceleration = in.vector<Vec4>();
  p.density = in.vector<float>();
  p.pressure = in.vector<float>();
  fluid.warmStart = in.vector<Vec4>();
  fluid.externalById = in.vector<Vec4>();
  fluid.drainedByOutlet = in.vector<std::uint64_t>();
  fluid.densityIsState = in.value<bool>();
  const std::size_t n = p.id.size();
  for (std::size_t size : {p.position.size(), p.velocity.size(), p.acceleration.size(),
                           p.density.size(), p.pressure.size()})
    if (size != n) in.mismatch("its particle arrays differ in length");
  if (!fluid.warmStart.empty() && fluid.warmStart.size() != n) in.mismatch("its warm start");
  if (fluid.drainedByOutlet.size() != outlets) in.mismatch("its outlets");
  for (std::uint32_t id : p.id)
    if (id >= nextId) in.mismatch("a particle id past the ids given out");
  return fluid;
}

// The objects' part of a state: the engine's world, its pacing and the exchange between it and
// the fluid, and what the fluid keeps of them.
struct ObjectsState {
  objects::WorldState world;
  ObjectRunner::Pacing pacing;
  ObjectExchange::Snapshot exchange;
  std::uint64_t seenPublication = 0;
  float objectMaxSpeed = 0.0f;
  std::uint64_t contactPairs = 0;
  std::vector<Vec3> fluidForceOnObject, contactForceOnObject;
  HostContainment containment;

  void write(StateWriter& out) const {
    writeWorld(out, world);
    out.value(pacing.credit);
    out.value(pacing.pendingTime);
    writeSurface(out, exchange.front);
    out.value(exchange.version);
    out.vector(exchange.impulse);
    out.value(exchange.span);
    out.vector(exchange.lastMean);
    out.value(seenPublication);
    out.value(objectMaxSpeed);
    out.value(contactPairs);
    out.vector(fluidForceOnObject);
    out.vector(contactForceOnObject);
    out.vector(containment.containerById);
    out.vector(containment.insideById);
    out.vector(containment.firstExitById);
  }
  // Checked against the engine's particle handles, the scene's objects and its fluid.
  static ObjectsState read(StateReader& in, std::size_t handles, std::size_t objectCount,
                           std::size_t initialFluid) {
    ObjectsState o;
    o.world = readWorld(in);
    o.pacing.credit = in.value<double>();
    o.pacing.pendingTime = in.value<double>();
    o.exchange.front = readSurface(in);
    o.exchange.version = in.value<std::uint64_t>();
    o.exchange.impulse = in.vector<Vec3>();
    o.exchange.span = in.value<double>();
    o.exchange.lastMean = in.vector<Vec3>();
    o.seenPublication = in.value<std::uint64_t>();
    o.objectMaxSpeed = in.value<float>();
    o.contactPairs = in.value<std::uint64_t>();
    o.fluidForceOnObject = in.vector<Vec3>();
    o.contactForceOnObject = in.vector<Vec3>();
    o.containment.containerById = in.vector<std::int32_t>();
    o.containment.insideById = in.vector<std::uint32_t>();
    o.containment.firstExitById = in.vector<Vec4>();
    if (o.exchange.impulse.size() != handles || o.exchange.lastMean.size() != handles)
      in.mismatch("its object particles' forces");
    for (std::uint32_t h : o.exchange.front.handle)
      if (h >= handles) in.mismatch("an object particle past the engine's");
    if (o.fluidForceOnObject.size() != objectCount || o.contactForceOnObject.size() != objectCount)
      in.mismatch("its objects' forces");
    const std::size_t ids = o.containment.containerById.size();
    if (o.containment.insideById.size() != ids || o.containment.firstExitById.size() != ids ||
        ids < initialFluid)
      in.mismatch("its leak tracking");
    return o;
  }
};

}  // namespace sph::sim
