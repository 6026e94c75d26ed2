// Simulation::saveState / loadState: a simulation that loads another's state steps on exactly as
// the other does (the same bytes on the CPU backend, on any thread count), and a state that is
// not one of this scene's, or that was damaged, is refused saying why and changes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "backends.hpp"
#include "frame_checks.hpp"
#include "scene/scene_loader.hpp"
#include "scene_builders.hpp"
#include "sph/error.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

using testing::expectIdenticalFrames;

std::string stateOf(const Simulation& sim) {
  std::ostringstream out;
  sim.saveState(out);
  return out.str();
}

void load(Simulation& sim, const std::string& state) {
  std::istringstream in(state);
  sim.loadState(in);
}

// `scene` run for `before` steps and saved; then on for `after` steps, against a second
// simulation (on `threads` threads) that loads the state and takes the same steps.
void expectResumedRunMatches(const Scene& scene, int before, int after, int threads = 1) {
  Simulation original(scene);
  for (int i = 0; i < before; ++i) original.step();
  const std::string state = stateOf(original);
  const FrameStats savedStats = original.stats();
  for (int i = 0; i < after; ++i) original.step();

  SimulationOptions options;
  options.threads = threads;
  Simulation resumed(scene, options);
  load(resumed, state);
  EXPECT_EQ(resumed.time(), savedStats.time);
  EXPECT_EQ(resumed.stepCount(), savedStats.steps);
  EXPECT_EQ(resumed.stats().surfaceCount, savedStats.surfaceCount);
  for (int i = 0; i < after; ++i) resumed.step();
  expectIdenticalFrames(original.frame(), resumed.frame());
  EXPECT_EQ(original.stepCount(), resumed.stepCount());
  EXPECT_EQ(original.lastDt(), resumed.lastDt());
  EXPECT_EQ(original.removedCount(), resumed.removedCount());
  EXPECT_EQ(original.emittedCount(), resumed.emittedCount());
  EXPECT_EQ(original.lastSolve().densityIterations, resumed.lastSolve().densityIterations);
  EXPECT_EQ(original.stats().densityIterations, resumed.stats().densityIterations);
}

Scene fallingBlock() {
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.fluid.blocks[0].box.min[1] = 0.05;
  scene.fluid.blocks[0].box.max[1] = 0.15;
  scene.fluid.blocks[0].velocity = {0.3, 0, -0.2};
  return scene;
}

TEST(Checkpoint, TheWeaklyCompressibleSolverStepsOnByteForByte) {
  expectResumedRunMatches(fallingBlock(), 60, 60);
}

TEST(Checkpoint, TheIncompressibleSolverStepsOnWithItsWarmStartOnAnotherThreadCount) {
  Scene scene = fallingBlock();
  scene.fluid.solver = FluidSolver::Dfsph;
  scene.fluid.kernel = KernelKind::CubicSpline;
  expectResumedRunMatches(scene, 25, 25, 2);
}

TEST(Checkpoint, ContinuityDensityIsCarriedOver) {
  Scene scene = fallingBlock();
  scene.fluid.density = DensityModel::Continuity;
  expectResumedRunMatches(scene, 60, 60);
}

// Emitters, an outlet and probes, as the shipped pipe scene has them, once fluid has been put in
// and drained.
TEST(Checkpoint, EmittersOutletsAndProbesPickUpWhereTheyStood) {
  Scene scene = scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/pipe_flow.json",
                                 {"fluid.spacing=0.01", "fluid.blocks.0.min=[0.2, 0.07, 0.02]"});
  // Under the sanitizers saved once the outlet has drained (from 0.01 s) and run on past the
  // emitter's second layer (0.033 s).
  const double save = testing::kSanitized ? 0.02 : 0.3, end = testing::kSanitized ? 0.04 : 0.4;
  Simulation original(scene);
  original.advanceTo(save);
  ASSERT_GT(original.emittedCount(), 0u);
  ASSERT_GT(original.outletStats()[0].particles, 0u);
  original.takeProbeRows();
  const std::string state = stateOf(original);
  original.advanceTo(end);

  Simulation resumed(scene);
  load(resumed, state);
  resumed.advanceTo(end);
  expectIdenticalFrames(original.frame(), resumed.frame());
  EXPECT_EQ(original.outletStats()[0].particles, resumed.outletStats()[0].particles);
  const std::vector<ProbeRow> a = original.takeProbeRows(), b = resumed.takeProbeRows();
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].time, b[k].time);
    EXPECT_EQ(a[k].values, b[k].values);
  }
}

TEST(Checkpoint, LiveParametersChangedBeforeTheSaveComeBack) {
  const Scene scene = fallingBlock();
  Simulation original(scene);
  LiveParameters live = original.liveParameters();
  live.viscosity *= 3.0;
  live.gravity = {0.0, -5.0, 1.0};
  original.setLiveParameters(live);
  for (int i = 0; i < 30; ++i) original.step();
  const std::string state = stateOf(original);
  for (int i = 0; i < 30; ++i) original.step();

  Simulation resumed(scene);
  load(resumed, state);
  EXPECT_EQ(resumed.liveParameters().viscosity, live.viscosity);
  EXPECT_EQ(resumed.liveParameters().gravity, live.gravity);
  for (int i = 0; i < 30; ++i) resumed.step();
  expectIdenticalFrames(original.frame(), resumed.frame());
}

// Loads `state` into a fresh simulation of `scene`, expecting InputError with `expected` in its
// message, and the simulation as it was.
void expectRefused(const Scene& scene, const std::string& state, const std::string& expected) {
  Simulation sim(scene);
  for (int i = 0; i < 3; ++i) sim.step();
  const ParticleFrame before = sim.frame();
  try {
    load(sim, state);
    ADD_FAILURE() << "a state that should be refused was loaded (" << expected << ")";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
  expectIdenticalFrames(before, sim.frame());
  EXPECT_EQ(sim.stepCount(), 3u);
  sim.step();  // and it still steps
}

TEST(Checkpoint, ADamagedOrForeignStateIsRefusedSayingWhyAndChangesNothing) {
  const Scene scene = fallingBlock();
  Simulation source(scene);
  for (int i = 0; i < 10; ++i) source.step();
  const std::string state = stateOf(source);

  std::string flipped = state;
  flipped[state.size() / 2] = char(flipped[state.size() / 2] ^ 0x10);
  expectRefused(scene, flipped, "checksum");
  expectRefused(scene, state.substr(0, state.size() - 100), "cut short");
  expectRefused(scene, "", "not a saved sph simulation state");
  expectRefused(scene, "{\"fluid\": 1}", "not a saved sph simulation state");
  std::string otherVersion = state;
  otherVersion[8] = char(otherVersion[8] + 1);  // the format version follows the magic word
  expectRefused(scene, otherVersion, "format");

  Scene wider = scene;
  wider.fluid.blocks[0].box.max[0] = 0.09;
  expectRefused(wider, state, "fluid particles");
  Scene incompressible = scene;
  incompressible.fluid.solver = FluidSolver::Dfsph;
  expectRefused(incompressible, state, "fluid.solver");
}

// With objects: the engine's world (in its own thread, as shipped), its exchange with the fluid
// and the leak tracking, saved from `start` on and compared `steps` steps later. Returns the
// objects' statistics then, and the particles leaked.
struct ObjectsAfter {
  std::vector<ObjectStats> objects;
  std::size_t leaked = 0;
};
ObjectsAfter expectObjectsResume(const Scene& scene, double start, int steps) {
  Simulation original(scene);
  original.advanceTo(start);
  const std::string state = stateOf(original);
  for (int i = 0; i < steps; ++i) original.step();

  SimulationOptions options;
  options.threads = 2;
  Simulation resumed(scene, options);
  load(resumed, state);
  for (int i = 0; i < steps; ++i) resumed.step();
  expectIdenticalFrames(original.frame(), resumed.frame());
  const std::vector<ObjectStats> a = original.objectStats(), b = resumed.objectStats();
  EXPECT_EQ(a.size(), b.size());
  for (std::size_t o = 0; o < a.size() && o < b.size(); ++o) {
    EXPECT_EQ(a[o].centreOfMass, b[o].centreOfMass) << a[o].name;
    EXPECT_EQ(a[o].fluidForce, b[o].fluidForce) << a[o].name;
    EXPECT_EQ(a[o].contactForce, b[o].contactForce) << a[o].name;
    EXPECT_EQ(a[o].brokenSprings, b[o].brokenSprings) << a[o].name;
  }
  EXPECT_EQ(original.leakedIds(), resumed.leakedIds());
  EXPECT_EQ(original.leakPositions(), resumed.leakPositions());
  return {a, original.leakedIds().size()};
}

Scene shipped(const char* name, std::vector<std::string> overrides = {}) {
  return scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/" + name, overrides);
}

// The sanitizers' build checks that the state goes through clean on a coarser artery, where a
// step takes a fraction of the time: at half the fluid's resolution, or at 1.25 mm where the
// tear bleeds (from 0.028 s; at 2 mm it does not).
Scene squeezedArtery() {
  return testing::kSanitized ? shipped("artery_squeeze.json", {"fluid.spacing=0.002"})
                             : shipped("artery_squeeze.json");
}
Scene tornArtery() {
  return testing::kSanitized ? shipped("artery_tear.json", {"fluid.spacing=0.00125"})
                             : shipped("artery_tear.json");
}

TEST(Checkpoint, FloatingRigidBodiesResume) {
  expectObjectsResume(shipped("floating_bodies.json", {"fluid.spacing=0.02"}), 0.1, 40);
}

// The clamp closing on the vessel (XPBD, contact constraints, a kinematic path), once it moves.
TEST(Checkpoint, TheSqueezedArteryResumes) {
  const ObjectsAfter after = expectObjectsResume(squeezedArtery(), 0.2, 40);
  EXPECT_GT(std::abs(after.objects[1].contactForce[1]), 0.0) << "the clamp presses";
}

// Torn: the broken springs and cut particles come back, and the blood that left.
TEST(Checkpoint, TheTornArteryResumesWithItsBrokenSpringsAndLeaks) {
  const ObjectsAfter after =
      expectObjectsResume(tornArtery(), testing::kSanitized ? 0.03 : 0.36, 30);
  EXPECT_GT(after.objects[0].brokenSprings, 0u);
  EXPECT_GT(after.leaked, 0u) << "the tear bleeds by then";
}

// The position solver's substeps with the objects as boundary particles: the clamp closing.
TEST(Checkpoint, TheSqueezedArteryUnderThePositionSolverResumes) {
  Scene scene = squeezedArtery();
  scene.fluid.solver = FluidSolver::Pbf;
  scene.interaction.coupling = ObjectCoupling::Boundary;
  const ObjectsAfter after = expectObjectsResume(scene, 0.2, 40);
  EXPECT_GT(std::abs(after.objects[1].contactForce[1]), 0.0) << "the clamp presses";
}

// An engine stepping every second fluid step (its pacing and the forces it has been handed so
// far are state too), objects as boundary particles of the incompressible solver, and a clamp
// the user has steered away from its keyframes.
TEST(Checkpoint, PacingBoundaryCouplingAndSteeringResume) {
  Scene scene = shipped("floating_bodies.json",
                        {"fluid.spacing=0.02", "object_engine.rate=0.5", "fluid.solver=dfsph",
                         "fluid.kernel=cubic_spline", "interaction.coupling=boundary"});
  expectObjectsResume(scene, 0.05, testing::kSanitized ? 6 : 15);  // sanitized, 0.3 s a step
  Scene artery = squeezedArtery();
  Simulation original(artery);
  original.advanceTo(0.05);
  original.steerObject("clamp_top", {0.0, -0.002, 0.0}, 0.02);
  for (int i = 0; i < 5; ++i) original.step();
  const std::string state = stateOf(original);
  for (int i = 0; i < 60; ++i) original.step();
  Simulation resumed(artery);
  load(resumed, state);
  for (int i = 0; i < 60; ++i) resumed.step();
  expectIdenticalFrames(original.frame(), resumed.frame());
}

TEST(Checkpoint, AStateWithObjectsIsNotTakenByASceneWithout) {
  Simulation withObjects(shipped("floating_bodies.json", {"fluid.spacing=0.02"}));
  withObjects.step();
  expectRefused(fallingBlock(), stateOf(withObjects), "not a state of this scene");
}

}  // namespace
}  // namespace sph
