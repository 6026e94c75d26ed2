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

  // A stage of a step: its name, the StepProfile bucket its time adds to, and what it does.
  struct Stage {
    const char* name;
    double StepProfile::*bucket;
    void (Impl::*run)();
  };
  // The step of this scene's solver, in order: only the stages that have work in this scene
  // (sim/wcsph_step.cpp, sim/dfsph_step.cpp). Made again when an object engine is attached.
  std::vector<Stage> stages;
  std::vector<Stage> stageList() const {
    return scene.fluid.solver == FluidSolver::Dfsph ? dfsphStages() : wcsphStages();
  }
  std::vector<Stage> wcsphStages() const;
  std::vector<Stage> dfsphStages() const;
  // The stages after the solver's own, the same for every solver (sim/step_end.cpp).
  void addStepEnd(std::vector<Stage>& list) const;
  StepProfile profile;
  double time = 0.0;
  double dt = 0.0;
  double until = 0.0;  // the step being taken may not pass it
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

  // The stages (Stage::run): each does the work its name says, and is in a step's list only
  // where the scene gives it work.
  void buildGrid() {
    removed += engine->buildGrid();
    surfaceMeasured = false;  // the particles move in the engine's order: measured when asked
  }
  void sumDensity() {
    engine->computeDensityAndPressure();
    neighboursListed = true;
  }
  void advanceDensity() { engine->integrateDensity(float(movedFor)); }
  void computeForces() { engine->computeForces(); }
  void chooseTimeStep() { dt = nextTimeStep(until); }
  void integrate() {
    clamped += engine->integrate(float(dt));
    movedFor = dt;
    time = (dt == until - time) ? until : time + dt;
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

  Impl(const Scene& s, const SimulationOptions& options);

  // The probes read the state as it is now (sim/probes.hpp).
  void sampleProbes();

  bool probesWallForces() const {
    for (const ProbeDesc& p : scene.probes)
      if (p.kind == ProbeKind::Force && !p.wall.empty()) return true;
    return false;
  }
  void mapWallParticles(const sim::Walls& walls);
  // The fluid's force on each probed wall this step, summed in the engine's wall order (the
  // same for any thread count); a pass over the probed walls' particles.
  void collectWallForces();

  // Flow in (sim/emitters.hpp): the fluid just past each emitter moves at its velocity, and
  // the layers due by now enter.
  void driveInflow() { engine->driveInflow(inflowZones); }
  void emit();

  // Across a periodic face an object must never meet its own image: the fluid between them
  // would find both.
  void checkPeriodicExtent(const objects::ObjectWorld& world) const;

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
                                              const std::vector<Vec3>& positions);

  // Meteer 2011, §7, step 2: the engine's newest surface particles. Boundary particles are
  // read before the density pass that counts them; contact partners when the contacts are
  // computed, the engine's step having run beside the fluid's passes until then.
  bool objectsAsBoundary() const { return coupled() && interactionParams.boundary; }
  void receiveObjects();
  // An attached engine's publication (whose handles and object ids publish() checked): radii
  // whose contact reach the fluid's grid can search. Remembers each handle's object.
  void checkExternalSurface(const ObjectSurface& surface);

  // Meteer 2011, §7, steps 2-4: the objects' newest surface particles, collisions and contact
  // forces.
  void contactObjects() {
    receiveObjects();
    contactPairs = engine->computeContacts(interactionParams);
  }
  // With boundary coupling the pass finds no contact forces, only whether each particle is
  // still inside its container.
  void checkContainment() { contactPairs = engine->computeContacts(interactionParams); }

  // The fluid's forces on the objects' particles: the contact forces, or with boundary
  // coupling the reactions of the pressure the solves have just given, at the positions they
  // were computed at.
  void collectObjectForces();

  // The engine receives this step's forces and takes its own step(s) over dt.
  void advanceObjects();

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
                   const objects::ObjectWorld* world) const;

  // Only the lattice points that start clear of the object's influence spheres.
  void keepInside(std::vector<Vec3>& points, const std::string& name,
                  const objects::ObjectWorld* world) const;

  std::size_t objectIndex(const std::string& name) const;

  // The incompressible solver's two solves.
  bool incompressible() const { return scene.fluid.solver == FluidSolver::Dfsph; }
  void solveDivergence();
  void solveDensity();
  fluid::SolverSettings solverSettings(fluid::SolverTarget target) const;

  double nextTimeStep(double until);

  // Meteer 2011, §8.3: contacts stay resolved, and no object particle moves more than a quarter of
  // the fluid's radius in a step, so nothing tunnels.
  double objectTimeStep() const;

  static constexpr double kShortestStep = 1e-9;  // s
  [[noreturn]] void failStalled(double dt, const fluid::StepMeasures& m);
  [[noreturn]] void failRunaway(const fluid::StepMeasures& m, double speedLimit);
  [[noreturn]] void fail(float bound);
};

}  // namespace sph
