// Scenes whose objects are Bullet's (object_engine.type "bullet"): BulletEngine::forScene makes
// them, attachTo couples them, frames show them, and what Bullet cannot take is refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "bullet_test_support.hpp"
#include "scene/scene_loader.hpp"
#include "sph/bullet_engine.hpp"
#include "sph/core/constants.hpp"
#include "sph/error.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

using testing::kSanitized;

Scene shippedScene() {
  return scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/bullet_bodies.json");
}

// The shipped scene: its three bodies with their masses, falling into the water, in frames,
// named in the statistics, nothing leaking from the soft ball.
TEST(BulletScene, TheShippedSceneFallsIntoTheWater) {
  const Scene scene = shippedScene();
  ASSERT_EQ(scene.objectEngine.type, ObjectEngineKind::Bullet);
  Simulation sim(scene);
  EXPECT_THROW(sim.step(), std::logic_error) << "stepped without its Bullet world";
  auto engine = BulletEngine::forScene(scene);
  ASSERT_EQ(engine->bodyCount(), 3u);
  EXPECT_NEAR(engine->body(0).mass, 500.0 * 0.12 * 0.08 * 0.10, 1e-9);
  EXPECT_NEAR(engine->body(1).mass, 750.0 * 0.10 * 0.06 * 0.10, 1e-9);
  EXPECT_NEAR(engine->body(2).mass, 1000.0 * 4.0 * kPi * 0.05 * 0.05 * 0.01, 1e-6);
  EXPECT_TRUE(engine->body(2).soft);
  engine->attachTo(sim);
  const double start = engine->body(0).centre[1];
  while (sim.time() < (kSanitized ? 0.01 : 0.2)) {
    sim.step();
    engine->step();
  }
  if (!kSanitized) {
    EXPECT_LT(engine->body(0).centre[1], start - 0.05) << "the pine box did not fall";
  }
  const ParticleFrame frame = sim.frame(false);
  std::size_t objectParticles = 0;
  for (std::uint8_t kind : frame.kind)
    objectParticles += kind == std::uint8_t(ParticleKind::Object);
  std::size_t published = 0;
  for (std::size_t b = 0; b < engine->bodyCount(); ++b) published += engine->body(int(b)).particles;
  EXPECT_EQ(objectParticles, published) << "frames hold every body's particles";
  EXPECT_EQ(sim.objectStats().at(2).name, "rubber_ball");
  EXPECT_EQ(sim.leakedCount(), 0u);
}

// What Bullet cannot take, refused with the object's key.
TEST(BulletScene, WhatBulletCannotTakeIsRefusedByName) {
  const auto refusal = [](const auto& change) {
    Scene scene = shippedScene();
    change(scene);
    try {
      BulletEngine::forScene(scene);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal([](Scene& s) {
              s.objects[1].motion = ObjectMotion::Kinematic;
            }).find("objects[1].motion"),
            std::string::npos);
  EXPECT_NE(refusal([](Scene& s) {
              s.objects[2].shape.kind = ShapeKind::Capsule;
            }).find("objects[2].shape.type"),
            std::string::npos);
  EXPECT_NE(refusal([](Scene& s) {
              s.objects[2].deformable.stiffness = 100.0;
            }).find("objects[2].deformable"),
            std::string::npos);
  EXPECT_NE(refusal([](Scene& s) {
              s.objects[0].shape.kind = ShapeKind::Capsule;
              s.objects[0].shape.axis = {1, 0, 0};
            }).find("objects[0].shape.axis"),
            std::string::npos);
}

}  // namespace
}  // namespace sph
