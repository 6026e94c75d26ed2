// Contacts of XPBD deformables as constraints (src/objects/contact_constraints.*): they bound
// no substep, yet a clamp squeezing an XPBD tube lets nothing through and feels the tube push
// back; a deformable resting on a floor presses on it with its weight; two deformables that
// collide keep their total momentum.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "object_scenes.hpp"

namespace sph::objects {
namespace {

using test::box;
using test::settings;
using test::sphere;
using test::tube;

constexpr double kDt = 1e-3;

// A tube (radius 1 cm, 8 cm long, 100 N/m) pinned at both ends under a plate that moves 8 mm
// down over 0.1 s, its bottom layer one particle diameter above the tube's top.
std::vector<ObjectDesc> clampOnXpbdTube(int substeps) {
  ObjectDesc vessel = tube({0, 0, 0}, 0.01, 0.08, 0.0025);
  vessel.deformable.model = DeformableModel::Xpbd;
  vessel.deformable.substeps = substeps;
  vessel.deformable.stiffness = 100.0;
  vessel.deformable.pinned = {{{-1, -1, -1}, {-0.035, 1, 1}}, {{0.035, -1, -1}, {1, 1, 1}}};
  ObjectDesc clamp =
      box({0, 0.0125 + 0.00125, 0}, {0.01, 0.00125, 0.015}, 0.0025, ObjectMotion::Kinematic);
  clamp.name = "clamp";
  clamp.keyframes = {{0.1, {0, -0.008, 0}, {0, 0, 0}}};
  return {vessel, clamp};
}

WorldSettings stiffContacts(Vec3 gravity = {0, 0, 0}) {
  WorldSettings s = settings(gravity);
  s.contact = {500.0f, 0.05f, 0.01f};
  return s;
}

// Only the clamp's speed bounds the substep (a quarter of a particle's radius a substep), not
// the contact spring, which as a force would ask for 0.3 / ω = 5.3e-5 s.
TEST(ContactConstraints, BoundNoSubstep) {
  const ObjectWorld world(clampOnXpbdTube(1), stiffContacts());
  const double clampSpeed = 0.008 / 0.1, radius = 0.5 * 0.0025;
  EXPECT_NEAR(world.stableSubstep(), 0.25 * radius / clampSpeed, 1e-9);
  const double m = world.particles().mass[0];
  EXPECT_GT(world.stableSubstep(), 50.0 * 0.3 / std::sqrt(500.0 / m));
}

// One substep a millisecond leaves the tube's network far softer than its springs (k h²/m =
// 6.4); 16 hold it (0.025).
TEST(ContactConstraints, ClampSqueezesAnXpbdTubeAndNothingGetsThrough) {
  ObjectWorld world(clampOnXpbdTube(16), stiffContacts());
  const ObjectInfo vessel = world.info(0);
  const ParticleState& p = world.particles();
  double at40ms = 0.0;
  for (int ms = 1; ms <= 130; ++ms) {
    world.step(kDt, {});
    const Vec3 onClamp = world.contactForce(1);
    // Every correction moves both sides: what the clamp feels, the tube feels reversed.
    EXPECT_NEAR(world.contactForce(0).y, -onClamp.y, 1e-4 * std::abs(onClamp.y) + 1e-9);
    if (ms == 40) at40ms = onClamp.y;
  }
  EXPECT_GT(at40ms, 0.0);
  EXPECT_GT(world.contactForce(1).y, 3.0 * at40ms);
  float plateBottom = 1.0f, tubeTopMiddle = -1.0f;
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_TRUE(isFinite(p.position[i]));
    if (p.object[i] == 1) plateBottom = std::min(plateBottom, p.position[i].y);
  }
  for (std::size_t i = vessel.firstParticle; i < vessel.firstParticle + vessel.particleCount; ++i) {
    if (std::abs(p.position[i].x) < 0.008f && std::abs(p.position[i].z) < 0.015f) {
      EXPECT_LT(p.position[i].y, plateBottom - 0.5f * 0.0025f) << "particle " << i;
    }
    if (std::abs(p.position[i].x) < 0.003f)
      tubeTopMiddle = std::max(tubeTopMiddle, p.position[i].y);
  }
  EXPECT_LT(tubeTopMiddle, 0.0045f);  // pushed down from 1 cm with the plate
}

// The same clamp on the same tube, once as springs meeting it by contact forces, once as XPBD
// meeting it by constraints: once the plate stops, it feels the same push (measured 0.0509 and
// 0.0495 N).
TEST(ContactConstraints, AsConstraintsTheySqueezeAsTheForcesDo) {
  std::vector<ObjectDesc> springs = clampOnXpbdTube(16);
  springs[0].deformable.model = DeformableModel::Springs;
  double mean[2] = {0.0, 0.0};
  int k = 0;
  for (const std::vector<ObjectDesc>& objects : {springs, clampOnXpbdTube(16)}) {
    ObjectWorld world(objects, stiffContacts());
    for (int ms = 1; ms <= 130; ++ms) {
      world.step(kDt, {});
      if (ms > 100) mean[k] += world.contactForce(1).y / 30.0;
    }
    ++k;
  }
  EXPECT_GT(mean[0], 0.03);
  EXPECT_NEAR(mean[1], mean[0], 0.05 * mean[0]);
}

// A closed deformable sphere (radius 2 cm) dropped 1 cm onto a kinematic floor: once it rests,
// the floor carries its weight.
TEST(ContactConstraints, ADeformableRestsOnAFloorWithItsWeight) {
  ObjectDesc floor = box({0, -0.04, 0}, {0.06, 0.005, 0.06}, 0.005, ObjectMotion::Kinematic);
  floor.name = "floor";
  ObjectDesc ball =
      sphere({0, -0.035 + 0.005 + 0.02 + 0.01, 0}, 0.02, 0.005, ObjectMotion::Deformable);
  ball.deformable.model = DeformableModel::Xpbd;
  ball.deformable.substeps = 2;
  ball.deformable.stiffness = 200.0;
  ObjectWorld world({floor, ball}, stiffContacts({0, -9.81f, 0}));
  for (int ms = 0; ms < 1500; ++ms) world.step(kDt, {});
  double mean = 0.0;
  constexpr int kSteps = 200;
  for (int ms = 0; ms < kSteps; ++ms) {
    world.step(kDt, {});
    mean += world.contactForce(0).y / kSteps;
  }
  const ObjectInfo rest = world.info(1);
  const double weight = rest.mass * 9.81;
  EXPECT_LT(length(rest.velocity), 0.005f);
  EXPECT_NEAR(-mean, weight, 0.02 * weight);  // the floor is pushed down
  for (std::size_t i = rest.firstParticle; i < rest.firstParticle + rest.particleCount; ++i)
    EXPECT_GT(world.particles().position[i].y, -0.035f + 0.0025f) << "below the floor's surface";
}

// Two deformable spheres meet head on, gravity off: whatever their collision does to their
// shapes, their total momentum stays what it was.
TEST(ContactConstraints, ACollisionKeepsTheTotalMomentum) {
  ObjectDesc left = sphere({-0.025, 0, 0}, 0.02, 0.005, ObjectMotion::Deformable);
  left.name = "left";
  left.velocity = {0.5, 0.05, 0};
  ObjectDesc right = sphere({0.025, 0.004, 0}, 0.02, 0.005, ObjectMotion::Deformable);
  right.name = "right";
  right.velocity = {-0.3, 0, 0};
  right.density = 2000.0;
  for (ObjectDesc* d : {&left, &right}) {
    d->deformable.model = DeformableModel::Xpbd;
    d->deformable.substeps = 2;
    d->deformable.stiffness = 200.0;
  }
  ObjectWorld world({left, right}, stiffContacts());
  // Σ m v, and Σ m |v| for the scale of the tolerance.
  const auto momentum = [&] {
    Vec3d sum{0, 0, 0};
    double scale = 0.0;
    for (std::size_t o = 0; o < 2; ++o) {
      const ObjectInfo info = world.info(o);
      const Vec3 v = info.velocity;
      const double vs[3] = {v.x, v.y, v.z};
      for (int a = 0; a < 3; ++a) sum[a] += info.mass * vs[a];
      scale += info.mass * double(length(v));
    }
    return std::pair<Vec3d, double>{sum, scale};
  };
  const auto [before, size] = momentum();
  double touched = 0.0;
  for (int ms = 0; ms < 150; ++ms) {
    world.step(kDt, {});
    touched = std::max(touched, double(length(world.contactForce(0))));
  }
  EXPECT_GT(touched, 0.0) << "they never met";
  const auto [after, unused] = momentum();
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(after[a], before[a], 1e-5 * size) << "axis " << a;
  EXPECT_LT(world.info(0).velocity.x, 0.5f * 0.5f);  // the light one was slowed or turned back
}

}  // namespace
}  // namespace sph::objects
