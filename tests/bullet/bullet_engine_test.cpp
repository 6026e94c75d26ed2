// Bullet's rigid bodies beside the fluid (sph/bullet_engine.hpp): Newton's third law through the
// exchange, a light box afloat at Archimedes' draft, a granite ball on the floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "../sim/fluid_momentum.hpp"
#include "bullet_test_support.hpp"
#include "sph/bullet_engine.hpp"
#include "sph/core/constants.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

constexpr double kSpacing = 0.01;

using testing::kSanitized;

// A tank of water 0.14 m deep, with room above it.
Scene tank() {
  Scene s;
  s.name = "bullet_tank";
  s.sourcePath = "bullet_tank (test)";
  s.fluid.spacing = kSpacing;
  s.fluid.viscosity = 0.05;
  s.domain.box = {{-0.05, -0.05, -0.05}, {0.35, 0.45, 0.21}};
  FluidBlock water;
  water.box = {{0, 0, 0}, {0.3, 0.14, 0.16}};
  water.hydrostatic = true;
  s.fluid.blocks.push_back(water);
  s.walls.push_back(WallDesc::tank({{0, 0, 0}, {0.3, 0.3, 0.16}}, 2, false));
  s.calibration.maxExpectedSpeed = 1.5;
  s.output.format = FrameFormat::None;
  return s;
}

// Away from the bodies (x > 0.2): the top particle of each lattice column, averaged, plus half a
// spacing.
double waterLevel(const ParticleFrame& f) {
  std::map<std::pair<int, int>, double> top;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double x = f.position[3 * i], y = f.position[3 * i + 1], z = f.position[3 * i + 2];
    if (x < 0.2) continue;
    const auto key = std::make_pair(int(std::floor(x / kSpacing)), int(std::floor(z / kSpacing)));
    const auto it = top.find(key);
    if (it == top.end() || y > it->second) top[key] = y;
  }
  double sum = 0.0;
  for (const auto& column : top) sum += column.second;
  return sum / double(top.size()) + 0.5 * kSpacing;
}

enum class Shape { Box, Sphere, Capsule, Hull, SoftBall };

std::string shapeName(const ::testing::TestParamInfo<Shape>& info) {
  const char* names[] = {"box", "sphere", "capsule", "hull", "soft_ball"};
  return names[int(info.param)];
}

// An octahedron 8 cm across, its vertices given about a corner rather than its centre.
std::vector<BulletEngine::Vec3d> octahedron() {
  const double a = 0.04;
  return {{2 * a, a, a}, {0, a, a}, {a, 2 * a, a}, {a, 0, a}, {a, a, 2 * a}, {a, a, 0}};
}

class BulletShapes : public ::testing::TestWithParam<Shape> {};

// Fluid + Bullet body, gravity off: a block of water thrown at a body of each shape; what the
// fluid loses the body gains (a soft ball's nodes: within 1e-4, the rigid bodies within 1e-5).
TEST_P(BulletShapes, FluidAndBulletBodyConserveMomentum) {
  Scene scene;
  scene.name = "block_hits_bullet_body";
  scene.sourcePath = "block_hits_bullet_body (test)";
  scene.gravity = {0, 0, 0};
  scene.fluid.spacing = kSpacing;
  scene.fluid.viscosity = 0.1;
  scene.domain.box = {{-1, -1, -1}, {1, 1, 1}};
  FluidBlock block;
  block.box = {{-0.1, -0.05, -0.05}, {0.0, 0.05, 0.05}};
  block.velocity = {1.0, 0.1, 0.0};
  scene.fluid.blocks.push_back(block);
  Simulation sim(scene);
  BulletEngine engine(testing::bulletSettings(scene));
  switch (GetParam()) {
    case Shape::Box:
      engine.addBox({0.03, 0.04, 0.03}, {0.06, 0.01, 0.0}, 800.0);
      break;
    case Shape::Sphere:
      engine.addSphere(0.04, {0.07, 0.01, 0.0}, 800.0);
      break;
    case Shape::Capsule:
      engine.addCapsule(0.03, 0.04, {0.06, 0.01, 0.0}, 800.0);
      break;
    case Shape::Hull:
      engine.addConvexHull(octahedron(), {0.03, -0.03, -0.04}, 800.0);
      break;
    case Shape::SoftBall: {
      BulletEngine::SoftMaterial rubber;
      rubber.volumeStiffness = 1.0;
      engine.addSoftBall(0.04, {0.07, 0.01, 0.0}, 0.2, rubber);
      break;
    }
  }
  const bool soft = GetParam() == Shape::SoftBall;
  ASSERT_GT(engine.body(0).particles, soft ? 100u : 20u);
  sim.attachObjectEngine(engine.exchange());
  const std::array<double, 4> before = testing::fluidMomentum(sim);
  while (sim.time() < (kSanitized ? 0.03 : 0.15)) {
    sim.step();
    engine.step();
  }
  const std::array<double, 4> after = testing::fluidMomentum(sim);
  const BulletEngine::Body body = engine.body(0);
  // Under the sanitizers the run is too short for the water to reach every body.
  if (!kSanitized) {
    EXPECT_GT(body.velocity[0], soft ? 0.05 : 0.02) << "the fluid did not push the body";
  }
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(after[a] + body.mass * body.velocity[a], before[a],
                (soft ? 1e-4 : 1e-5) * before[3])
        << "axis " << a;
}

INSTANTIATE_TEST_SUITE_P(Shapes, BulletShapes,
                         ::testing::Values(Shape::Box, Shape::Sphere, Shape::Capsule, Shape::Hull,
                                           Shape::SoftBall),
                         shapeName);

// Mass from the exact volume, centred on the centroid, particles half a spacing inside.
TEST(BulletEngine, ShapesHaveTheirVolumesCentresAndSurfaceLayers) {
  BulletEngine engine({});
  const double a = 0.04;
  engine.addCapsule(0.03, 0.05, {0, 0, 0}, 1000.0);
  engine.addConvexHull(octahedron(), {1.0, 2.0, 3.0}, 1000.0);
  EXPECT_NEAR(engine.body(0).mass, 1000.0 * kPi * 0.03 * 0.03 * (0.05 + 0.04), 1e-9);
  EXPECT_NEAR(engine.body(1).mass, 1000.0 * 4.0 / 3.0 * a * a * a, 1e-9);
  const BulletEngine::Body hull = engine.body(1);
  EXPECT_NEAR(hull.centre[0], 1.0 + a, 1e-6);
  EXPECT_NEAR(hull.centre[1], 2.0 + a, 1e-6);
  EXPECT_NEAR(hull.centre[2], 3.0 + a, 1e-6);
  ObjectSurface s;  // the bodies as published
  std::uint64_t seen = 0;
  engine.exchange()->readIfNew(seen, [&](const ObjectSurface& published) { s = published; });
  ASSERT_EQ(s.size(), engine.body(0).particles + hull.particles);
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec4 x = s.position[k];
    if (s.object[k] == 0) {  // the capsule: 0.5 to 1.5 spacings under its surface
      const double y = std::clamp(double(x.y), -0.025, 0.025);
      const double depth = 0.03 - std::hypot(double(x.x), double(x.y) - y, double(x.z));
      EXPECT_GE(depth, 0.5 * kSpacing - 1e-6);
      EXPECT_LT(depth, 1.5 * kSpacing + 1e-6);
    } else {  // the octahedron |x|+|y|+|z| <= a about its centre: its faces' distance
      const double depth = (a - (std::abs(x.x - hull.centre[0]) + std::abs(x.y - hull.centre[1]) +
                                 std::abs(x.z - hull.centre[2]))) /
                           std::sqrt(3.0);
      EXPECT_GE(depth, 0.5 * kSpacing - 1e-5);
      EXPECT_LT(depth, 1.5 * kSpacing + 1e-5);
    }
  }
  EXPECT_THROW(engine.addConvexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 0, 0}, 1000.0),
               std::logic_error);  // after the exchange
  BulletEngine flat({});
  EXPECT_THROW(flat.addConvexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {0, 0, 0}, 1000.0),
               std::invalid_argument);
}

TEST(BulletEngine, ABoxOfHalfTheWatersDensityFloatsAtItsArchimedesDraft) {
  const Scene scene = tank();
  Simulation sim(scene);
  BulletEngine engine(testing::bulletSettings(scene));
  const BulletEngine::Vec3d half{0.07, 0.04, 0.05};
  engine.addBox(half, {0.1, 0.14 + 0.02 + half[1], 0.08}, 500.0);  // 2 cm above the water
  sim.attachObjectEngine(engine.exchange());
  const double duration = kSanitized ? 0.05 : 1.5;
  double draftSum = 0.0;
  int samples = 0;
  double next = 1.2;
  while (sim.time() < duration) {
    sim.step(duration);
    engine.step();
    if (sim.time() + 1e-9 < next) continue;
    draftSum += waterLevel(sim.frame(false)) - (engine.body(0).centre[1] - half[1]);
    ++samples;
    next += 0.05;
  }
  if (kSanitized) GTEST_SKIP() << "too short under the sanitizers to settle; it ran clean";
  const double archimedes = 2.0 * half[1] * 500.0 / 1000.0;
  ASSERT_GE(samples, 6);
  std::printf("mean draft over 1.2-1.5 s: %.4f m, Archimedes %.4f m (%+.1f %%)\n",
              draftSum / samples, archimedes, 100.0 * (draftSum / samples / archimedes - 1.0));
  EXPECT_NEAR(draftSum / samples, archimedes, 0.10 * archimedes);
  // Afloat, upright: the water's torques balance.
  const BulletEngine::Body box = engine.body(0);
  for (double w : box.spin) EXPECT_LT(std::abs(w), 0.5);
}

TEST(BulletEngine, AGraniteBallRestsOnTheFloor) {
  const Scene scene = tank();
  Simulation sim(scene);
  BulletEngine engine(testing::bulletSettings(scene));
  const double r = 0.03;
  engine.addSphere(r, {0.15, 0.2, 0.08}, 2700.0);
  engine.addStaticBox({1.0, 0.5, 1.0}, {0.15, -0.5, 0.08});  // the tank's floor, for Bullet
  sim.attachObjectEngine(engine.exchange());
  const double duration = kSanitized ? 0.05 : 1.0;
  while (sim.time() < duration) {
    sim.step(duration);
    engine.step();
  }
  if (kSanitized) GTEST_SKIP() << "too short under the sanitizers to sink; it ran clean";
  const BulletEngine::Body ball = engine.body(0);
  std::printf("ball at 1 s: centre %.4f m above the floor (radius %.3f), speed %.2e m/s\n",
              ball.centre[1], r, std::hypot(ball.velocity[0], ball.velocity[1], ball.velocity[2]));
  EXPECT_NEAR(ball.centre[1], r, 0.1 * r) << "on the floor";
  EXPECT_LT(std::hypot(ball.velocity[0], ball.velocity[1], ball.velocity[2]), 0.02) << "at rest";
  EXPECT_EQ(sim.fluidCount(), sim.calibration().fluidParticles);
}

// Bullet in a thread of its own, in lock-step with the fluid: the same bytes as stepping the
// two one after the other.
TEST(BulletEngine, InItsOwnThreadTheRunIsTheSameAsInline) {
  const Scene scene = tank();
  const auto run = [&](bool ownThread) {
    Simulation sim(scene);
    BulletEngine::Settings s = testing::bulletSettings(scene);
    s.ownThread = ownThread;
    BulletEngine engine(s);
    engine.addBox({0.05, 0.03, 0.05}, {0.1, 0.2, 0.08}, 500.0);
    engine.addSoftBall(0.04, {0.22, 0.2, 0.08}, 0.1, {});
    sim.attachObjectEngine(engine.exchange());
    while (sim.time() < (kSanitized ? 0.01 : 0.15)) {
      sim.step();
      engine.step();
    }
    engine.wait();
    return std::make_pair(sim.frame(false).position, engine.body(1).centre);
  };
  const auto inline_ = run(false), threaded = run(true);
  EXPECT_EQ(inline_.first, threaded.first) << "the fluid's positions differ";
  EXPECT_EQ(inline_.second, threaded.second) << "the ball's centre differs";
}

TEST(BulletEngine, MisuseIsRefused) {
  BulletEngine engine({});
  EXPECT_THROW(engine.exchange(), std::logic_error);  // nothing to exchange
  EXPECT_THROW(engine.step(), std::logic_error);
  EXPECT_THROW(engine.addBox({0.1, 0.1, 0.1}, {0, 0, 0}, 0.0), std::invalid_argument);
  engine.addSphere(0.05, {0, 0, 0}, 1000.0);
  EXPECT_GT(engine.exchange()->handleCount(), 0u);
  EXPECT_THROW(engine.addSphere(0.05, {0, 0, 0}, 1000.0), std::logic_error);
  EXPECT_THROW(engine.body(1), std::out_of_range);
  EXPECT_THROW(BulletEngine({0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace sph
