// Flow in and out: an emitter puts its rate × time of fluid in, a layer at a time, on the
// lattice and at its speed; an outlet takes out, and counts, what enters it; the shipped pipe
// carries its flow from the emitter to the outlet without losing a particle through its wall.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "backends.hpp"
#include "io/scene_loader.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

constexpr double kSpacing = 0.01;
constexpr double kSpeed = 0.5;  // m/s
constexpr double kPeriod = kSpacing / kSpeed;

// No gravity, no walls: a disc emitter across x, and a small block far from its stream (a
// scene has fluid to start with).
Scene emitterScene() {
  Scene s;
  s.name = "emitter";
  s.sourcePath = "emitter (test)";
  s.gravity = {0, 0, 0};
  s.fluid.spacing = kSpacing;
  s.fluid.kernel = KernelKind::CubicSpline;
  s.fluid.viscosity = 0.02;
  s.domain.box = {{0, 0, 0}, {0.4, 0.3, 0.3}};
  FluidBlock block;
  block.box = {{0.3, 0.02, 0.02}, {0.34, 0.06, 0.06}};
  s.fluid.blocks.push_back(block);
  EmitterDesc e;
  e.name = "nozzle";
  e.shape = EmitterShape::Disc;
  e.center = {0.05, 0.15, 0.15};
  e.radius = 0.03;
  e.direction = {1, 0, 0};
  e.speed = kSpeed;
  e.start = 0.01;
  s.emitters.push_back(e);
  return s;
}

class Emitters : public ::testing::TestWithParam<Backend> {};

TEST_P(Emitters, PutTheirRateTimesTheTimeOnTheLatticeAtTheirSpeed) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  const Scene scene = emitterScene();
  Simulation sim(scene, testing::on(GetParam()));
  const std::uint64_t initial = sim.fluidCount();
  const double mass = sim.calibration().mass;
  const FlowStats before = sim.emitterStats().at(0);
  EXPECT_EQ(before.particles, 0u);
  const double layer = before.rate * kPeriod;  // particles a layer
  EXPECT_GT(layer, 20.0);                      // π (3 cm)² at 1 cm: 28
  const int periods = testing::kSanitized ? 3 : 6;
  for (int k = 1; k <= periods; ++k) {
    // Just before the k-th period ends: k layers put, the k-th at the emitter's plane.
    const double t = scene.emitters[0].start + k * kPeriod - 1e-6;
    sim.advanceTo(t);
    const FlowStats now = sim.emitterStats().at(0);
    const double expected = before.rate * mass * (t - scene.emitters[0].start);
    EXPECT_NEAR(now.mass, expected, mass) << "after " << k << " periods";
    EXPECT_EQ(now.particles, std::uint64_t(k * std::lround(layer)));
    EXPECT_EQ(sim.fluidCount(), initial + now.particles);
  }
  // The stream: inside the emitter's cylinder, from its plane to as far as it has run, moving
  // at its speed, and no layer put on top of another.
  const ParticleFrame frame = sim.frame(false);
  const double travelled = kSpeed * (sim.time() - scene.emitters[0].start);
  std::size_t inStream = 0;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const float* x = &frame.position[3 * i];
    if (x[0] > 0.25) continue;  // the starting block
    ++inStream;
    EXPECT_GT(x[0], 0.05 - 0.5 * kSpacing);
    EXPECT_LT(x[0], 0.05 + travelled + kSpacing);
    EXPECT_LT(std::hypot(x[1] - 0.15, x[2] - 0.15), 0.03 + 0.5 * kSpacing);
    EXPECT_NEAR(frame.velocity[3 * i], kSpeed, 0.1 * kSpeed);
    EXPECT_LT(frame.density[i], 1.03 * scene.fluid.restDensity) << "particle " << frame.id[i];
  }
  EXPECT_EQ(inStream, sim.emittedCount());
}

TEST_P(Emitters, PutNothingBeforeTheirStartOrAfterTheirEnd) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Scene scene = emitterScene();
  scene.emitters[0].start = 0.02;
  scene.emitters[0].end = 0.02 + 2 * kPeriod - 1e-6;
  Simulation sim(scene, testing::on(GetParam()));
  sim.advanceTo(0.02);
  EXPECT_EQ(sim.emittedCount(), 0u);
  sim.advanceTo(0.02 + 5 * kPeriod);
  const FlowStats f = sim.emitterStats().at(0);
  EXPECT_EQ(f.particles, std::uint64_t(2 * std::lround(f.rate * kPeriod)));
}

SPH_ON_EVERY_BACKEND(Emitters);

class Outlets : public ::testing::TestWithParam<Backend> {};

TEST_P(Outlets, RemoveAndCountWhatEntersThem) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Scene scene;
  scene.name = "outlet";
  scene.sourcePath = "outlet (test)";
  scene.gravity = {0, 0, 0};
  scene.fluid.spacing = kSpacing;
  scene.fluid.viscosity = 0.02;
  scene.domain.box = {{0, 0, 0}, {0.4, 0.2, 0.2}};
  FluidBlock block;
  block.box = {{0.02, 0.05, 0.05}, {0.1, 0.13, 0.13}};
  block.velocity = {2.0, 0, 0};
  scene.fluid.blocks.push_back(block);
  scene.outlets.push_back({"sink", {{0.2, 0.0, 0.0}, {0.4, 0.2, 0.2}}});
  scene.outlets.push_back({"elsewhere", {{0.0, 0.15, 0.15}, {0.05, 0.2, 0.2}}});
  Simulation sim(scene, testing::on(GetParam()));
  const std::uint64_t initial = sim.fluidCount();
  sim.advanceTo(0.08);  // the block's front has entered, its back not yet
  const std::vector<FlowStats> midway = sim.outletStats();
  ASSERT_EQ(midway.size(), 2u);
  EXPECT_EQ(midway[0].name, "sink");
  EXPECT_GT(midway[0].particles, 0u);
  EXPECT_LT(midway[0].particles, initial);
  EXPECT_EQ(midway[0].particles + sim.fluidCount(), initial);
  EXPECT_NEAR(midway[0].mass, double(midway[0].particles) * sim.calibration().mass, 1e-12);
  sim.advanceTo(0.25);  // every particle through, and the run goes on empty
  const std::vector<FlowStats> after = sim.outletStats();
  EXPECT_EQ(after[0].particles, initial);
  EXPECT_EQ(after[1].particles, 0u);
  EXPECT_EQ(sim.fluidCount(), 0u);
  EXPECT_EQ(sim.removedCount(), initial);
}

SPH_ON_EVERY_BACKEND(Outlets);

// Every fluid particle of the shipped pipe is inside the pipe (its radius, and a spacing's
// give) or past its open end, on its way into the drain: none went through the wall.
TEST(PipeFlow, CarriesTheFlowFromTheEmitterToTheOutletWithoutLosingAParticle) {
  const Scene scene = io::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/pipe_flow.json");
  Simulation sim(scene);
  const std::uint64_t initial = sim.fluidCount();
  const double until = testing::kSanitized ? 0.02 : 0.3;
  const double pipeEnd = 0.4;
  const double radius = 0.03 + scene.fluid.spacing;
  while (sim.time() < until) {
    sim.advanceTo(std::min(until, sim.time() + 0.02));
    const ParticleFrame frame = sim.frame(false);
    for (std::size_t i = 0; i < frame.size(); ++i) {
      const float* x = &frame.position[3 * i];
      if (x[0] > pipeEnd) continue;
      ASSERT_LT(std::hypot(x[1] - 0.1, x[2] - 0.05), radius)
          << "particle " << frame.id[i] << " at t = " << sim.time() << " s, x = " << x[0];
      ASSERT_GT(x[0], -0.0025 - scene.fluid.spacing) << "particle " << frame.id[i];
    }
    const std::uint64_t drained = sim.outletStats().at(0).particles;
    ASSERT_EQ(initial + sim.emittedCount(), sim.fluidCount() + drained)
        << "every particle is in the pipe or drained, at t = " << sim.time() << " s";
  }
  EXPECT_GT(sim.emittedCount(), 0u);
  EXPECT_GT(sim.outletStats().at(0).particles, 0u);
}

}  // namespace
}  // namespace sph
