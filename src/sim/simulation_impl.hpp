// The state behind sph::Simulation, shared by the files that implement it.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "scene/scene_loader.hpp"
#include "sim/calibration.hpp"
#include "sim/emitters.hpp"
#include "sim/fluid_engine.hpp"
#include "sim/object_clearance.hpp"
#include "sim/object_runner.hpp"
#include "sim/probes.hpp"
#include "sim/sampling.hpp"
#include "sim/scene_size.hpp"
#include "sim/walls.hpp"
#include "sph/core/contact.hpp"
#include "sph/core/kernels.hpp"
#include "sph/core/time_step.hpp"
#include "sph/devices.hpp"
#include "sph/error.hpp"
#include "sph/simulation.hpp"

namespace sph {

namespace detail {

template <class Stage>
inline double timedMs(Stage&& stage) {
  const auto start = std::chrono::steady_clock::now();
  stage();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace detail

struct Simulation::Impl {
  Scene scene;
  Calibration calibration;
  fluid::FluidParameters params;
  std::unique_ptr<sim::FluidEngine> engine;
  StepProfile profile;
  double time = 0.0;
  double dt = 0.0;
  std::uint64_t steps = 0;
  int threads = 0;  // SimulationOptions::threads
  std::uint64_t removed = 0;
  std::uint64_t clamped = 0;
  std::uint64_t initialFluid = 0;
  // The surface flags (|∇c| in acceleration.w) are measured when a frame or statistics want
  // them, not in every step: the step needs them only for surface tension.
  bool neighboursListed = false;  // a density pass has run: the surface can be measured
  mutable bool surfaceMeasured = false;
  void measureSurfaceIfStale() const {
    if (!surfaceMeasured && neighboursListed) engine->measureSurface();
    surfaceMeasured = true;
  }
  // The interaction with objects; objects is null when the scene has none. An engine of the
  // user's own, attached instead (Simulation::attachObjectEngine), is known only through its
  // exchange.
  std::unique_ptr<sim::ObjectRunner> objects;
  std::shared_ptr<ObjectExchange> externalExchange;
  std::vector<std::int32_t> externalContainers;  // by fluid id: the attached object holding it
  ObjectSurface externalSurface;  // the attached engine's newest publication read, for frames
  std::vector<std::int32_t> externalObjectOfHandle;  // from the newest publication read
  bool coupled() const { return objects || externalExchange; }
  ObjectExchange& exchange() { return objects ? objects->exchange() : *externalExchange; }
  interaction::InteractionParameters interactionParams{};
  std::uint64_t seenPublication = 0;
  float objectMaxSpeed = 0.0f;
  std::uint64_t contactPairs = 0;
  sim::HostObjectForces objectForces;
  std::vector<Vec3> fluidForceOnObject;     // by object, last step
  std::vector<Vec3> contactForceOnObject;   // by object, over the engine's last finished step
  std::vector<Vec3> fluidForceOnWall;       // by wall, last step; only when a probe asks
  std::vector<std::size_t> wallOfParticle;  // in the engine's wall order
  std::unique_ptr<sim::ProbeSampler> probes;
  // Continuity density: advanced at the next density pass over the step that moved the
  // particles (none before the first).
  double movedFor = 0.0;
  void advanceDensity() {
    if (params.continuityDensity) engine->integrateDensity(float(movedFor));
  }
  // Flow in: the emitters, and the id the next particle they put gets (after the objects').
  sim::Emitters emitters;
  fluid::InflowZones inflowZones;
  std::uint32_t nextId = 0;
  // The incompressible solver's last solves, and its counts since the start.
  fluid::SolverReport divergenceReport;
  fluid::SolverReport densityReport;
  struct {
    std::uint64_t densityIterations = 0;
    std::uint64_t divergenceIterations = 0;
    std::uint64_t unconvergedSolves = 0;
  } solverTotals;

  Impl(const Scene& s, const SimulationOptions& options)
      : scene(scene::validateScene(s)), threads(checkedThreads(options.threads)), emitters(scene) {
    const backend::ScopedThreadCount passThreads(threads);
    backend::requireCompiledInstructionSet();
    sim::refuseIfTooLarge(scene, sim::availableBytes());  // before anything large is made
    calibration = sim::calibrate(scene);
    const sim::Walls walls(scene);
    sim::EngineSetup setup = sim::engineSetup(scene, calibration, walls);
    if (options.neighborListLength > 0) setup.neighborStride = options.neighborListLength;
    setup.walk = options.cpuPasses == CpuPasses::Batched ? fluid::NeighborWalk::Batched
                                                         : fluid::NeighborWalk::OneAtATime;
    params = setup.params;
    dt = calibration.initialDt;
    std::optional<objects::ObjectWorld> world;
    // Under Bullet the scene's objects are the attached engine's (sph/bullet_engine.hpp).
    if (!scene.objects.empty() && scene.objectEngine.type == ObjectEngineKind::Builtin) {
      objects::WorldSettings settings = sim::worldSettings(scene, calibration);
      // Objects rest on the walls that hold the fluid; they meet the walls across a periodic
      // face through their own images, not the walls' (which follow the walls' particles).
      settings.staticParticles.assign(
          setup.walls.begin(), setup.walls.begin() + std::ptrdiff_t(walls.firstParticle().back()));
      settings.staticRadius = static_cast<float>(0.5 * scene.fluid.spacing);
      world.emplace(scene.objects, settings);
      interactionParams = sim::interactionParameters(scene, calibration);
      checkContactReach(*world);
      checkPeriodicExtent(*world);
    }

    sampleFluid(setup, walls, world ? &*world : nullptr);
    initialFluid = setup.positions.size();
    engine =
        useCuda(options) ? sim::makeCudaEngine(setup, options.device) : sim::makeCpuEngine(setup);

    calibration.fluidParticles = initialFluid;
    calibration.boundaryParticles = engine->wallCount();
    if (world) {
      calibration.objectParticles = world->particles().size();
      engine->setContainers(containers(*world, setup.positions));
      fluidForceOnObject.assign(world->objectCount(), Vec3{0, 0, 0});
      contactForceOnObject.assign(world->objectCount(), Vec3{0, 0, 0});
      objects = std::make_unique<sim::ObjectRunner>(std::move(*world), scene.objectEngine.rate,
                                                    scene.objectEngine.ownThread);
    }
    if (probesWallForces()) mapWallParticles(walls);
    inflowZones = emitters.zones();
    nextId = std::uint32_t(initialFluid + engine->wallCount() + calibration.objectParticles);
    // Density and pressure of the initial state, so stats and frame 0 are meaningful.
    removed += engine->buildGrid();
    engine->computeDensityAndPressure();
    if (params.continuityDensity) engine->keepDensity(setup.densities);
    probes = std::make_unique<sim::ProbeSampler>(scene, scene.fluid.spacing);
    sampleProbes();
  }

  // The probes read the state as it is now (sim/probes.hpp).
  void sampleProbes() {
    if (probes->empty()) return;
    probes->record(time, engine->samplePoints(probes->points()),
                   {fluidForceOnObject, contactForceOnObject, fluidForceOnWall});
  }

  bool probesWallForces() const {
    for (const ProbeDesc& p : scene.probes)
      if (p.kind == ProbeKind::Force && !p.wall.empty()) return true;
    return false;
  }
  void mapWallParticles(const sim::Walls& walls) {
    const sim::HostWalls host = engine->downloadWalls();
    const std::vector<std::size_t>& first = walls.firstParticle();
    wallOfParticle.resize(host.id.size());
    for (std::size_t k = 0; k < host.id.size(); ++k) {
      const std::size_t sampled = host.id[k] - initialFluid;  // wall ids follow the fluid's
      wallOfParticle[k] =
          std::size_t(std::upper_bound(first.begin(), first.end(), sampled) - first.begin()) - 1;
    }
    fluidForceOnWall.assign(scene.walls.size(), Vec3{0, 0, 0});
    std::vector<std::uint8_t> probed(scene.walls.size(), 0), watched(host.id.size(), 0);
    for (const ProbeDesc& p : scene.probes)
      for (std::size_t w = 0; w < scene.walls.size(); ++w)
        if (p.kind == ProbeKind::Force && p.wall == scene.walls[w].name) probed[w] = 1;
    // A periodic image belongs to no wall (its index is past the last): never watched.
    for (std::size_t k = 0; k < watched.size(); ++k)
      watched[k] = wallOfParticle[k] < probed.size() ? probed[wallOfParticle[k]] : 0;
    engine->watchWalls(watched);
  }
  // The fluid's force on each probed wall this step, summed in the engine's wall order (the
  // same for any thread count); a pass over the probed walls' particles.
  void collectWallForces() {
    if (wallOfParticle.empty()) return;
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

  // Flow in (sim/emitters.hpp): the fluid just past each emitter moves at its velocity, and
  // the layers due by now enter.
  void driveInflow() {
    if (!emitters.empty()) engine->driveInflow(inflowZones);
  }
  void emit() {
    if (emitters.empty()) return;
    const sim::NewParticles fresh = emitters.emit(time);
    if (fresh.position.empty()) return;
    engine->addParticles(fresh.position, fresh.velocity, nextId);
    nextId += std::uint32_t(fresh.position.size());
  }

  // Across a periodic face an object must never meet its own image: the fluid between them
  // would find both.
  void checkPeriodicExtent(const objects::ObjectWorld& world) const {
    const objects::PeriodicSpace& space = world.periodicSpace();
    const objects::ParticleState& particles = world.particles();
    const double periods[3] = {space.length.x, space.length.y, space.length.z};
    for (std::size_t o = 0; o < world.objectCount() && space.any(); ++o) {
      const objects::ObjectInfo info = world.info(o);
      for (int a = 0; a < 3; ++a) {
        if (!space.periodic[a]) continue;
        double lo = 1e300, hi = -1e300;
        for (std::size_t i = info.firstParticle; i < info.firstParticle + info.particleCount; ++i) {
          const Vec3 x = particles.position[i];
          const double v = a == 0 ? x.x : a == 1 ? x.y : x.z;
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
        const double most = periods[a] - 2.0 * scene.fluid.supportRatio * scene.fluid.spacing;
        if (hi - lo > most)  // the extent of float positions, to the micrometre
          throw InputError(scene.sourcePath + ": objects[" + std::to_string(o) +
                           "]: expected the object to span at most the domain's period along " +
                           "periodic axis " + "xyz"[a] + " less two support radii (" +
                           formatNumber(most) + " m), got " +
                           formatNumber(std::round((hi - lo) * 1e6) / 1e6) + " m");
      }
    }
  }

  // Contacts are found through the fluid's grid (cell edge h) from the object particles.
  void checkContactReach(const objects::ObjectWorld& world) const {
    checkContactReach(world, interactionParams);
  }
  void checkContactReach(const objects::ObjectWorld& world,
                         const interaction::InteractionParameters& candidate) const {
    float largest = 0.0f;
    for (float r : world.particles().radius)
      largest = std::max(largest, interaction::contactReach(candidate, r));
    if (largest > params.h) {
      std::ostringstream message;
      message << scene.sourcePath << ": interaction.influence_ratio: the influence sphere reaches "
              << largest << " m, past the fluid's support radius h = " << params.h
              << " m; expected a smaller ratio or object spacing";
      throw InputError(message.str());
    }
  }

  // The object that holds each fluid particle at the start (the first whose interior has it).
  static std::vector<std::int32_t> containers(const objects::ObjectWorld& world,
                                              const std::vector<Vec3>& positions) {
    std::vector<std::int32_t> byId(positions.size(), -1);
    for (std::size_t o = 0; o < world.objectCount(); ++o) {
      if (!world.enclosesVolume(o)) continue;
      for (std::size_t i = 0; i < positions.size(); ++i) {
        if (byId[i] < 0 && world.interiorContains(o, positions[i], 0.0f))
          byId[i] = static_cast<std::int32_t>(o);
      }
    }
    return byId;
  }

  // Meteer 2011, §7, step 2: the engine's newest surface particles. Boundary particles are
  // read before the density pass that counts them; contact partners when the contacts are
  // computed, the engine's step having run beside the fluid's passes until then.
  bool objectsAsBoundary() const { return coupled() && interactionParams.boundary; }
  void receiveObjects() {
    if (!objects) {
      exchange().readIfNew(seenPublication, [&](const ObjectSurface& surface) {
        checkExternalSurface(surface);
        objectMaxSpeed = engine->setObjectSurface(surface, interactionParams);
        externalSurface = surface;
      });
      return;
    }
    objects->wait();
    objects->exchange().readIfNew(seenPublication, [&](const ObjectSurface& surface) {
      objectMaxSpeed = engine->setObjectSurface(surface, interactionParams);
    });
    // Read here, where the engine is known to be idle: the probes sample after the fluid's
    // step, while the engine may be running its own.
    for (std::size_t o = 0; o < contactForceOnObject.size(); ++o)
      contactForceOnObject[o] = objects->world().contactForce(o);
  }
  // An attached engine's publication (whose handles and object ids publish() checked): radii
  // whose contact reach the fluid's grid can search. Remembers each handle's object.
  void checkExternalSurface(const ObjectSurface& surface) {
    const auto refuse = [&](const std::string& what) {
      throw std::invalid_argument("attached object engine: its publication at t = " +
                                  formatNumber(surface.time) + " s " + what);
    };
    externalObjectOfHandle.assign(exchange().handleCount(), -1);
    std::int32_t objectCount = 0;
    for (std::size_t k = 0; k < surface.size(); ++k) {
      const float reach = interaction::contactReach(interactionParams, surface.position[k].w);
      if (!(reach <= params.h))
        refuse("has a particle of radius " + formatNumber(surface.position[k].w) +
               " m whose contact reach, " + formatNumber(reach) +
               " m, passes the fluid's support radius h = " + formatNumber(params.h) + " m");
      externalObjectOfHandle[surface.handle[k]] = surface.object[k];
      objectCount = std::max(objectCount, surface.object[k] + 1);
    }
    if (fluidForceOnObject.size() < std::size_t(objectCount))
      fluidForceOnObject.resize(std::size_t(objectCount), Vec3{0, 0, 0});
  }
  void receiveBoundaryObjects() {
    if (objectsAsBoundary()) receiveObjects();
  }

  // Meteer 2011, §7, steps 3-4: collisions and contact forces (with boundary coupling, only
  // whether each particle is still inside its container).
  void interact() {
    if (!coupled()) return;
    if (!objectsAsBoundary()) receiveObjects();
    contactPairs = engine->computeContacts(interactionParams);
  }

  // The fluid's forces on the objects' particles: the contact forces, or with boundary
  // coupling the reactions of the pressure the solves have just given, at the positions they
  // were computed at.
  void collectObjectForces() {
    if (!coupled()) return;
    if (objectsAsBoundary()) engine->addBoundaryForces();
    objectForces = engine->downloadObjectForces();
    if (objectsAsBoundary()) {  // the pairs within h that pushed
      contactPairs = 0;
      for (const Vec4& f : objectForces.force) contactPairs += std::uint64_t(f.w);
    }
  }

  // The engine receives this step's forces and takes its own step(s) over dt.
  void advanceObjects() {
    if (!coupled()) return;
    const std::size_t n = objectForces.handle.size();
    exchange().depositForces(objectForces.handle.data(), objectForces.force.data(), n, dt);
    std::fill(fluidForceOnObject.begin(), fluidForceOnObject.end(), Vec3{0, 0, 0});
    if (!objects) {  // the attached engine takes the forces and steps when it will
      for (std::size_t k = 0; k < n; ++k)
        fluidForceOnObject[externalObjectOfHandle[objectForces.handle[k]]] +=
            xyz(objectForces.force[k]);
      return;
    }
    const objects::ParticleState& particles = objects->world().particles();
    for (std::size_t k = 0; k < n; ++k)
      fluidForceOnObject[particles.object[objectForces.handle[k]]] += xyz(objectForces.force[k]);
    objects->advance(dt);
  }

  // Time, counts, leaks and objects: the statistics that need no copy of the fluid.
  FrameStats statsWithoutParticles(const Simulation& sim) const;

  static int checkedThreads(int threads) {
    if (threads < 0 || threads > kMaxThreads)
      throw std::invalid_argument(
          "SimulationOptions::threads: expected 0 (the caller's setting) "
          "to " +
          std::to_string(kMaxThreads) + ", got " + std::to_string(threads));
    return threads;
  }
  static constexpr int kMaxThreads = 1024;

  static bool useCuda(const SimulationOptions& options) {
    if (options.backend == Backend::Cuda) return true;
    return options.backend == Backend::Auto && !queryGpus().devices.empty();
  }

  void sampleFluid(sim::EngineSetup& setup, const sim::Walls& walls,
                   const objects::ObjectWorld* world) const {
    for (const auto& block : scene.fluid.blocks) {
      auto points = sim::sampleBlock(block.box, scene.fluid.spacing);
      walls.removeOverlap(points);
      if (!block.inside.empty()) keepInside(points, block.inside, world);
      if (world) {
        const int container = block.inside.empty() ? -1 : int(objectIndex(block.inside));
        sim::removeObjectOverlap(
            points, *world,
            [&](float radius) { return interaction::contactReach(interactionParams, radius); },
            container);
      }
      if (block.hydrostatic)
        sim::compressHydrostatically(points, block.box, scene.gravity, calibration.soundSpeed);
      const std::vector<float> rho =
          sim::restingDensities(points, block.box, block.hydrostatic, scene.gravity,
                                calibration.soundSpeed, scene.fluid.restDensity);
      setup.densities.insert(setup.densities.end(), rho.begin(), rho.end());
      const Vec3 v{float(block.velocity[0]), float(block.velocity[1]), float(block.velocity[2])};
      const Vec3 w{float(block.angularVelocity[0]), float(block.angularVelocity[1]),
                   float(block.angularVelocity[2])};
      const Vec3 centre{float(0.5 * (block.box.min[0] + block.box.max[0])),
                        float(0.5 * (block.box.min[1] + block.box.max[1])),
                        float(0.5 * (block.box.min[2] + block.box.max[2]))};
      setup.positions.insert(setup.positions.end(), points.begin(), points.end());
      for (const Vec3& p : points) {
        const Vec3 r = p - centre;  // v + ω × r
        setup.velocities.push_back(
            v + Vec3{w.y * r.z - w.z * r.y, w.z * r.x - w.x * r.z, w.x * r.y - w.y * r.x});
      }
    }
  }

  // Only the lattice points that start clear of the object's influence spheres.
  void keepInside(std::vector<Vec3>& points, const std::string& name,
                  const objects::ObjectWorld* world) const {
    const std::size_t o = objectIndex(name);
    const float margin = interaction::contactReach(
        interactionParams, world->particles().radius[world->info(o).firstParticle]);
    points.erase(std::remove_if(points.begin(), points.end(),
                                [&](Vec3 p) { return !world->interiorContains(o, p, margin); }),
                 points.end());
  }

  std::size_t objectIndex(const std::string& name) const {
    for (std::size_t o = 0; o < scene.objects.size(); ++o)
      if (scene.objects[o].name == name) return o;
    throw InputError(scene.sourcePath + ": fluid.blocks[].inside: no object is named '" + name +
                     "'");
  }

  // The incompressible solver's two solves (nothing for the weakly compressible one).
  bool incompressible() const { return scene.fluid.solver == FluidSolver::Dfsph; }
  void solveDivergence() {
    if (!incompressible()) return;
    engine->prepareSolver();
    divergenceReport = engine->solve(solverSettings(fluid::SolverTarget::NoDivergence),
                                     fluid::SolverTarget::NoDivergence, float(dt));
    solverTotals.divergenceIterations += std::uint64_t(divergenceReport.iterations);
    if (!scene.fluid.dfsph.divergenceSolve) divergenceReport.converged = true;  // not asked to
    if (!divergenceReport.converged) ++solverTotals.unconvergedSolves;
  }
  void solveDensity() {
    if (!incompressible() || !scene.fluid.dfsph.densitySolve) return;
    densityReport = engine->solve(solverSettings(fluid::SolverTarget::RestDensity),
                                  fluid::SolverTarget::RestDensity, float(dt));
    solverTotals.densityIterations += std::uint64_t(densityReport.iterations);
    if (!densityReport.converged) ++solverTotals.unconvergedSolves;
  }
  fluid::SolverSettings solverSettings(fluid::SolverTarget target) const {
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
    // Only the density solve: in the divergence solve it gained nothing.
    if (target == fluid::SolverTarget::RestDensity) s.chebyshev = float(d.chebyshev);
    // Six tenths of a full neighbourhood on the initial lattice: (4/3) π (h/d)³ neighbours.
    const double ratio = scene.fluid.supportRatio;
    s.minNeighbours = std::uint32_t(std::lround(0.6 * 4.0 / 3.0 * kPi * ratio * ratio * ratio));
    return s;
  }

  double chooseTimeStep(double until) {
    const fluid::StepMeasures m = engine->measureStep();
    const float bound = static_cast<float>(scene.failure.maxDensityError);
    if (!m.finite || m.maxDensityError > bound) fail(bound);
    // Past the scene's bound, by default ten times the speed of sound, or no fluid left at all:
    // a blow-up the density bound did not catch (a fixed step too long for the stiffness), not
    // a result.
    const double speedLimit = scene.failure.maxSpeed.value_or(
        10.0 * std::max(calibration.soundSpeed, 10.0 * calibration.maxExpectedSpeed));
    // A scene with flow in or out may run empty.
    const bool flows = !scene.emitters.empty() || !scene.outlets.empty();
    if (m.maxSpeed > speedLimit || (engine->fluidCount() == 0 && initialFluid > 0 && !flows))
      failRunaway(m, speedLimit);
    double next = scene.time.fixedDt
                      ? *scene.time.fixedDt
                      : longestStep(sim::stepLimits(scene, calibration), m.maxSpeed,
                                    m.maxAcceleration, coupled() ? objectTimeStep() : HUGE_VAL);
    const double remaining = until - time;
    // Under a nanosecond (the shortest time.fixed_dt a scene may ask for) the fluid has blown
    // up: its speeds or accelerations are beyond any scene's, and the run would crawl forever
    // or, once the step no longer moves the clock, hang.
    if (next < kShortestStep && next < remaining) failStalled(next, m);
    // Land exactly on `until` rather than leave a sliver of a step for later.
    if (next >= remaining)
      next = remaining;
    else if (next > 0.5 * remaining)
      next = 0.5 * remaining;
    return next;
  }

  // Meteer 2011, §8.3: contacts stay resolved, and no object particle moves more than a quarter of
  // the fluid's radius in a step, so nothing tunnels.
  double objectTimeStep() const {
    const double travel = travelTimeStep(0.25 * interactionParams.fluidRadius, objectMaxSpeed);
    if (interactionParams.boundary) return travel;  // no contact springs
    // The stiffest contact is at the centre of the influence sphere, where φ = e^β.
    const double contact = springTimeStep(calibration.mass, calibration.contactStiffness,
                                          distanceFunctionPeak(scene.interaction.distanceExponent));
    return std::min(contact, travel);
  }

  static constexpr double kShortestStep = 1e-9;  // s
  [[noreturn]] void failStalled(double dt, const fluid::StepMeasures& m) {
    std::ostringstream message;
    message << "simulation failed at step " << steps << " (t = " << time
            << " s): the time step fell to " << dt << " s, under " << kShortestStep
            << " s: the fastest particle moves at " << m.maxSpeed
            << " m/s, the largest acceleration is " << m.maxAcceleration << " m/s^2";
    throw SimulationFailure(message.str(), steps, 0, "time step");
  }
  [[noreturn]] void failRunaway(const fluid::StepMeasures& m, double speedLimit) {
    std::ostringstream message;
    message << "simulation failed at step " << steps << " (t = " << time << " s): ";
    if (engine->fluidCount() == 0) {
      message << "every fluid particle has left the domain (" << removed << " removed)";
      throw SimulationFailure(message.str(), steps, 0, "fluid count");
    }
    const sim::HostParticles fluid = engine->download();  // once, on the way out
    std::size_t fastest = 0;
    for (std::size_t i = 1; i < fluid.id.size(); ++i)
      if (lengthSquared(xyz(fluid.velocity[i])) > lengthSquared(xyz(fluid.velocity[fastest])))
        fastest = i;
    message << "particle " << fluid.id[fastest] << ": speed = " << m.maxSpeed
            << (scene.failure.maxSpeed ? " m/s, past failure.max_speed ("
                                       : " m/s, past ten times the speed of sound (")
            << speedLimit << " m/s)";
    throw SimulationFailure(message.str(), steps, fluid.id[fastest], "speed");
  }
  [[noreturn]] void fail(float bound) {
    const fluid::BadParticle bad = engine->findBadParticle(bound);
    std::ostringstream message;
    message << "simulation failed at step " << steps << " (t = " << time << " s): particle "
            << bad.id << ": " << bad.quantity << " = " << bad.value;
    if (bad.pastBound) message << ", past failure.max_density_error = " << bound;
    throw SimulationFailure(message.str(), steps, bad.id, bad.quantity);
  }
};

}  // namespace sph
