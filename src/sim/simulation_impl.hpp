// The state behind sph::Simulation: the scene and its calibration, the fluid's engine, and the
// parts with one concern each — the clock and its guard (sim/time_step_guard.hpp), the coupling
// with objects (sim/object_coupling.hpp), flow in (sim/inflow.hpp), what the run measures of
// itself (sim/outputs.hpp) and the incompressible solver's record (sim/solver_record.hpp). Its
// stages join them: each is a short function in the file of its solver's step.
#pragma once

#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "scene/scene_loader.hpp"
#include "sim/calibration.hpp"
#include "sim/decomposition.hpp"
#include "sim/fluid_engine.hpp"
#include "sim/inflow.hpp"
#include "sim/object_coupling.hpp"
#include "sim/outputs.hpp"
#include "sim/solver_record.hpp"
#include "sim/time_step_guard.hpp"
#include "sim/walls.hpp"
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
  int threads = 0;  // SimulationOptions::threads
  std::unique_ptr<sim::FluidEngine> engine;
  sim::Clock clock;
  sim::RunCounts counts;
  sim::ObjectCoupling coupling;
  sim::Inflow inflow;
  sim::Outputs outputs;
  sim::SolverRecord solves;
  StepProfile profile;
  // A run across processes (Simulation::distribute); none in one process.
  std::shared_ptr<sim::Decomposition> ranks;

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
    switch (scene.fluid.solver) {
      case FluidSolver::Dfsph:
        return dfsphStages();
      case FluidSolver::Pbf:
        return pbfStages();
      default:
        return wcsphStages();
    }
  }
  std::vector<Stage> wcsphStages() const;
  std::vector<Stage> dfsphStages() const;
  std::vector<Stage> pbfStages() const;
  // The stages after the solver's own, the same for every solver (sim/step_end.cpp), around
  // the solver's `move`: integration, or only the clock where the solver has moved the
  // particles itself.
  void addStepEnd(std::vector<Stage>& list, const Stage& move) const;

  // The stages (Stage::run): each does the work its name says, and is in a step's list only
  // where the scene gives it work.
  void buildGrid() {
    counts.removed += engine->buildGrid();
    outputs.surfaceMeasured = false;  // the particles move in the engine's order
  }
  void sumDensity() {
    engine->computeDensityAndPressure();
    outputs.neighboursListed = true;
  }
  void advanceDensity() { engine->integrateDensity(float(clock.movedFor)); }
  void computeForces() { engine->computeForces(); }
  void chooseTimeStep() {
    const double objectStep =
        coupling.coupled() ? coupling.timeStep(calibration, scene.interaction.distanceExponent)
                           : HUGE_VAL;
    clock.dt =
        sim::nextTimeStep(scene, calibration, *engine, clock, counts, objectStep, ranks.get());
  }
  void integrate() {
    counts.clamped += engine->integrate(float(clock.dt));
    advanceClock();
  }
  void advanceClock() {
    clock.movedFor = clock.dt;
    clock.time = (clock.dt == clock.until - clock.time) ? clock.until : clock.time + clock.dt;
  }
  // The position solver (sim/pbf_step.cpp).
  void predictPositions() { counts.clamped += engine->integrate(float(clock.dt)); }
  void solvePositions();
  void smoothVelocities() { engine->smoothVelocities(float(scene.fluid.pbf.xsph)); }
  // Meteer 2011, §7, step 2: boundary particles are read before the density pass that counts
  // them; contact partners when the contacts are computed, the engine's step having run beside
  // the fluid's passes until then.
  void receiveObjects() { coupling.receive(*engine, params.h); }
  // Meteer 2011, §7, steps 2-4.
  void contactObjects() {
    receiveObjects();
    coupling.computeContacts(*engine);
  }
  void checkContainment() { coupling.computeContacts(*engine); }
  void collectObjectForces() { coupling.collectForces(*engine, clock.dt); }
  void advanceObjects() { coupling.advance(clock.dt); }
  // A distributed run (sim/exchange_particles.cpp).
  void exchangeParticles();
  void refreshGhosts();
  void collectWallForces() { outputs.collectWallForces(*engine); }
  void driveInflow() { engine->driveInflow(inflow.zones); }
  // New particles have no neighbour lists until the next density pass: the surface is not
  // measured from the lists before it.
  void emit() {
    if (inflow.emit(*engine, clock.time) != 0) outputs.neighboursListed = false;
  }
  void sampleProbes() {
    outputs.sampleProbes(*engine, clock.time, coupling.fluidForceOnObject,
                         coupling.contactForceOnObject);
  }
  void solveDivergence();
  void solveDensity();
  fluid::SolverSettings solverSettings(fluid::SolverTarget target) const;
  // A solver that reports its solves (SolverStats): DFSPH's two, PBF's one (as its density solve).
  bool incompressible() const { return scene.fluid.solver != FluidSolver::Wcsph; }

  // Setting up (sim/simulation_setup.cpp).
  Impl(const Scene& s, const SimulationOptions& options);
  void sampleFluid(sim::EngineSetup& setup, const sim::Walls& walls,
                   const objects::ObjectWorld* world) const;
  // Only the lattice points that start clear of the object's influence spheres.
  void keepInside(std::vector<Vec3>& points, const std::string& name,
                  const objects::ObjectWorld* world) const;
  std::size_t objectIndex(const std::string& name) const;
  // The object that holds each fluid particle at the start (the first whose interior has it).
  static std::vector<std::int32_t> containers(const objects::ObjectWorld& world,
                                              const std::vector<Vec3>& positions);
  // Across a periodic face an object must never meet its own image: the fluid between them
  // would find both.
  void checkPeriodicExtent(const objects::ObjectWorld& world) const;
  static int checkedThreads(int threads);
  static constexpr int kMaxThreads = 1024;
  static bool useCuda(const SimulationOptions& options);

  // Time, counts, leaks and objects: the statistics that need no copy of the fluid.
  FrameStats statsWithoutParticles(const Simulation& sim) const;
  // The fluid as a frame takes it: a distributed run's ghosts left out.
  sim::HostParticles ownedParticles() const;
  // The statistics of every process's particles, each passing its own (a collective call).
  void addAcrossProcesses(FrameStats& stats) const;
  void measureSurfaceIfStale() const { outputs.measureSurfaceIfStale(*engine); }
};

}  // namespace sph
