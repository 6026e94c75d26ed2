// Same scene, same thread count: the same bytes out. The stable counting sort and exact max
// reductions make the trajectories independent of the thread count as well.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "backends.hpp"
#include "frame_checks.hpp"
#include "scene/scene_loader.hpp"
#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

ParticleFrame runFor(int threads, int steps) {
  backend::setThreadCount(threads);
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.fluid.blocks[0].box.min[1] = 0.05;
  scene.fluid.blocks[0].box.max[1] = 0.15;
  scene.fluid.blocks[0].velocity = {0.3, 0, -0.2};
  Simulation sim(scene);
  for (int i = 0; i < steps; ++i) sim.step();
  backend::setThreadCount(0);
  return sim.frame();
}

using testing::expectIdenticalFrames;

TEST(Determinism, SameThreadCountSameBytes) {
  expectIdenticalFrames(runFor(2, 200), runFor(2, 200));
}

TEST(Determinism, OneAndTwoThreadsAgree) {
  expectIdenticalFrames(runFor(1, 200), runFor(2, 200));
}

// The same through the library's option: its steps use the threads asked for, and leave the
// caller's own setting as it was.
TEST(Determinism, TheThreadsOptionGivesTheSameBytesAndKeepsTheCallersSetting) {
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.fluid.blocks[0].box.min[1] = 0.05;
  scene.fluid.blocks[0].box.max[1] = 0.15;
  backend::setThreadCount(2);
  std::vector<ParticleFrame> frames;
  for (int threads : {1, 2}) {
    SimulationOptions options;
    options.threads = threads;
    Simulation sim(scene, options);
    for (int i = 0; i < 100; ++i) sim.step();
    EXPECT_EQ(backend::threadCount(), 2);
    frames.push_back(sim.frame());
  }
  expectIdenticalFrames(frames[0], frames[1]);
  backend::setThreadCount(0);
  SimulationOptions tooMany;
  tooMany.threads = 100000;
  EXPECT_THROW(Simulation(scene, tooMany), std::invalid_argument);
}

// With objects: `scene` from `start` (once its clamp moves) for `steps` more steps on `threads`.
ParticleFrame squeeze(Scene scene, double start, int threads, int steps) {
  backend::setThreadCount(threads);
  Simulation sim(scene);
  sim.advanceTo(start);
  for (int i = 0; i < steps; ++i) sim.step();
  backend::setThreadCount(0);
  return sim.frame();
}

Scene shippedScene(const char* name) {
  return scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/" + name);
}

// The engine in its own thread, in lock-step, at half the fluid's rate, and the clamp
// squeezing the vessel. Fluid and object particles both come out byte-identical.
TEST(Determinism, WithObjectsInTheirThreadSameBytes) {
  Scene scene = shippedScene("artery_tear.json");
  scene.objectEngine.rate = 0.5;
  // The clamp starts at 0.05 s. Under the sanitizers, a memory check of the same thread, lock
  // step and exchange from the first step (the clamp's path is the artery tests').
  const double start = testing::kSanitized ? 0.0 : 0.06;
  const int steps = testing::kSanitized ? 30 : 100;
  const ParticleFrame a = squeeze(scene, start, 2, steps), b = squeeze(scene, start, 2, steps);
  expectIdenticalFrames(a, b);
  EXPECT_EQ(a.kind, b.kind);
  expectIdenticalFrames(a, squeeze(scene, start, 1, steps));
}

// The same under the incompressible solver with the objects as boundary particles: their
// volumes, the solves through them and the reactions they take.
TEST(Determinism, WithObjectsAsBoundaryParticlesSameBytes) {
  Scene scene = shippedScene("artery_squeeze.json");
  scene.fluid.solver = FluidSolver::Dfsph;
  scene.fluid.kernel = KernelKind::CubicSpline;
  scene.interaction.coupling = ObjectCoupling::Boundary;
  const double start = testing::kSanitized ? 0.0 : 0.055;
  const int steps = testing::kSanitized ? 10 : 20;
  const ParticleFrame a = squeeze(scene, start, 2, steps);
  expectIdenticalFrames(a, squeeze(scene, start, 2, steps));
  expectIdenticalFrames(a, squeeze(scene, start, 1, steps));
}

TEST(Determinism, TheRunMovedParticles) {
  const ParticleFrame start = runFor(2, 0), end = runFor(2, 200);
  EXPECT_NE(start.position, end.position);
}

// Flow in and out: the emitters' layers join the sorted arrays and the outlet drains them, the
// same on 1 and 2 threads (the shipped pipe, past its first layers and its first drained).
TEST(Determinism, WithEmittersAndOutletsSameBytes) {
  // Under the sanitizers at 1 cm, an eighth of the particles, from the outlet's first drained
  // (0.01 s) on.
  const Scene scene = testing::kSanitized
                          ? scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/pipe_flow.json",
                                             {"fluid.spacing=0.01"})
                          : shippedScene("pipe_flow.json");
  const double start = testing::kSanitized ? 0.01 : 0.03;
  const int steps = testing::kSanitized ? 10 : 40;
  const ParticleFrame a = squeeze(scene, start, 2, steps);
  expectIdenticalFrames(a, squeeze(scene, start, 1, steps));
}

// Objects across periodic faces: the shipped cells while the first of them, straddling the
// face from 0.2 s, moves through it (its centre at about 0.33 s), the same on 1 and 2 threads.
TEST(Determinism, WithObjectsAcrossPeriodicFacesSameBytes) {
  const Scene scene = shippedScene("cells_in_channel.json");
  const double start = testing::kSanitized ? 0.0 : 0.31;
  const int steps = testing::kSanitized ? 10 : 60;
  const ParticleFrame a = squeeze(scene, start, 2, steps);
  expectIdenticalFrames(a, squeeze(scene, start, 1, steps));
}

}  // namespace
}  // namespace sph
