// The object engine as a whole (src/objects/object_world.*): kinematic keyframes, contact
// between objects (a clamp squeezing a tube, a sphere resting on a floor), substepping,
// determinism and the errors for impossible geometry.
#include "objects/object_world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "object_scenes.hpp"
#include "sph/core/constants.hpp"
#include "sph/error.hpp"

namespace sph::objects {
namespace {

using test::box;
using test::settings;
using test::sphere;
using test::tube;

TEST(ObjectWorld, KinematicObjectFollowsItsKeyframes) {
  ObjectDesc d = box({0.2, 0.1, 0}, {0.02, 0.01, 0.01}, 0.005, ObjectMotion::Kinematic);
  // Still until 0.5 s after moving 0.1 m along x, then a quarter turn about z by 1 s.
  d.keyframes = {{0.5, {0.1, 0, 0}, {0, 0, 0}}, {1.0, {0.1, 0, 0}, {0, 0, 0.5 * kPi}}};
  ObjectWorld world({d}, settings({0, -9.81f, 0}));
  const std::vector<Vec3> start = world.particles().position;
  const Vec3 centre{0.2f, 0.1f, 0.0f};
  for (int s = 0; s < 250; ++s) world.step(1e-3, {});  // t = 0.25: halfway along x
  const ParticleState& p = world.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(test::distance(p.position[i], start[i] + Vec3{0.05f, 0, 0}), 0.0, 1e-6);
    EXPECT_NEAR(test::distance(p.velocity[i], {0.2f, 0, 0}), 0.0, 1e-6);  // 0.1 m / 0.5 s
  }
  for (int s = 0; s < 500; ++s) world.step(1e-3, {});  // t = 0.75: an eighth turn
  const double angle = 0.25 * kPi, omega = kPi;        // π/2 over 0.5 s
  const Vec3 turnedCentre = centre + Vec3{0.1f, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 r = start[i] - centre;
    const Vec3 arm{float(std::cos(angle) * r.x - std::sin(angle) * r.y),
                   float(std::sin(angle) * r.x + std::cos(angle) * r.y), r.z};
    EXPECT_NEAR(test::distance(p.position[i], turnedCentre + arm), 0.0, 1e-6);
    const Vec3 v{float(-omega * arm.y), float(omega * arm.x), 0.0f};  // ω ẑ × arm
    EXPECT_NEAR(test::distance(p.velocity[i], v), 0.0, 1e-5);
    EXPECT_NEAR(test::distance(p.normal[i], {0, 0, 0}), 1.0, 1e-5);
  }
  EXPECT_NEAR(world.info(0).velocity.x, 0.0, 1e-6);    // turning about its own centre
  for (int s = 0; s < 500; ++s) world.step(1e-3, {});  // held after the last keyframe
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 r = start[i] - centre;
    EXPECT_NEAR(test::distance(p.position[i], turnedCentre + Vec3{-r.y, r.x, r.z}), 0.0, 1e-6);
    EXPECT_EQ(length(p.velocity[i]), 0.0f);
  }
  // Forces do not move it.
  const std::vector<Vec3> push(p.size(), Vec3{1, 1, 1});
  const std::vector<Vec3> before = p.position;
  world.step(0.1, push);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p.position[i].x, before[i].x);
}

// A deformable tube (radius 1 cm, 8 cm long, 100 N/m springs) pinned at both ends, and a plate
// above its middle that moves 8 mm down over 0.1 s.
std::vector<ObjectDesc> clampOnTube() {
  ObjectDesc vessel = tube({0, 0, 0}, 0.01, 0.08, 0.0025);
  vessel.deformable.stiffness = 100.0;
  vessel.deformable.pinned = {{{-1, -1, -1}, {-0.035, 1, 1}}, {{0.035, -1, -1}, {1, 1, 1}}};
  // Bottom layer at 0.0125: one particle diameter above the tube's top.
  ObjectDesc clamp =
      box({0, 0.0125 + 0.00125, 0}, {0.01, 0.00125, 0.015}, 0.0025, ObjectMotion::Kinematic);
  clamp.name = "clamp";
  clamp.keyframes = {{0.1, {0, -0.008, 0}, {0, 0, 0}}};
  return {vessel, clamp};
}

WorldSettings clampSettings() {
  WorldSettings s = settings();
  s.contact = {50.0f, 0.005f, 0.0f};
  return s;
}

TEST(ObjectWorld, KinematicPlateSqueezesADeformableTube) {
  ObjectWorld world(clampOnTube(), clampSettings());
  const ObjectInfo vessel = world.info(0);
  const ParticleState& p = world.particles();
  const std::vector<Vec3> start = p.position;
  for (int s = 0; s < 130; ++s) world.step(1e-3, {});
  float plateBottom = 1.0f, tubeTopMiddle = -1.0f;
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_TRUE(isFinite(p.position[i]));
    if (p.object[i] == 1) plateBottom = std::min(plateBottom, p.position[i].y);
  }
  EXPECT_NEAR(plateBottom, 0.0125 - 0.008, 1e-6);
  for (std::size_t i = vessel.firstParticle; i < vessel.firstParticle + vessel.particleCount; ++i) {
    if (p.pinned[i]) {
      EXPECT_EQ(std::memcmp(&p.position[i], &start[i], sizeof(Vec3)), 0);
      continue;
    }
    // Nothing got through the plate: every tube particle stays below it, a contact apart.
    if (std::abs(p.position[i].x) < 0.008f && std::abs(p.position[i].z) < 0.015f) {
      EXPECT_LT(p.position[i].y, plateBottom - 0.5f * 0.0025f) << "particle " << i;
    }
    if (std::abs(p.position[i].x) < 0.003f)
      tubeTopMiddle = std::max(tubeTopMiddle, p.position[i].y);
    EXPECT_NEAR(length(p.normal[i]), 1.0, 1e-5);
  }
  // The top of the tube was pushed down from 1 cm with the plate (to 4.5 mm less a contact).
  EXPECT_LT(tubeTopMiddle, 0.0045f);
  EXPECT_GT(world.info(0).velocity.y, -0.1f);
}

// A kinematic floor, its top layer of particles at y = -0.03, and a rigid ball of radius 5 cm
// held `drop` above touching it, under gravity.
ObjectWorld ballAboveFloor(double drop) {
  ObjectDesc floor = box({0, -0.04, 0}, {0.12, 0.01, 0.12}, 0.01, ObjectMotion::Kinematic);
  floor.name = "floor";
  ObjectDesc ball = sphere({0, -0.03 + 0.01 + 0.05 + drop, 0}, 0.05, 0.01);
  WorldSettings s = settings({0, -9.81f, 0});
  s.contact = {5000.0f, 20.0f, 2.0f};
  return ObjectWorld({floor, ball}, s);
}

TEST(ObjectWorld, RigidSphereComesToRestOnAFloor) {
  ObjectWorld world = ballAboveFloor(0.05);  // lands at ~1 m/s
  const ParticleState& p = world.particles();
  const ObjectInfo ballInfo = world.info(1);
  double lowestGap = 1.0;
  for (int step = 0; step < 3000; ++step) {
    world.step(1e-3, {});
    for (std::size_t i = ballInfo.firstParticle; i < p.size(); ++i)
      lowestGap = std::min(lowestGap, double(p.position[i].y) - (-0.03));
  }
  const ObjectInfo rest = world.info(1);
  EXPECT_LT(length(rest.velocity), 0.01f);
  // Never closer than half a contact distance to the floor's top layer (no tunnelling). At rest
  // its lowest particles sit a contact distance (0.01) from floor particles, on top of one
  // (0.01 above the layer) or in the hollow between four (0.01/√2 above), less the overlap
  // that holds the weight.
  EXPECT_GT(lowestGap, 0.005);
  const double height = rest.centreOfMass.y - (-0.03) - 0.05;
  EXPECT_GT(height, 0.01 / std::sqrt(2.0) - 0.001);
  EXPECT_LT(height, 0.01);
  EXPECT_LT(std::abs(rest.centreOfMass.x), 0.05f);
}

// Each object's contact force (what a force probe on a clamp reads): nothing before the ball
// lands; then, over half a second of the ball settling on the floor, its impulse with gravity's
// is the ball's change of momentum, and the floor feels the opposite at every step.
TEST(ObjectWorld, ContactForcesAreTheImpulseThatHoldsTheBallUp) {
  ObjectWorld world = ballAboveFloor(0.02);
  world.step(1e-3, {});  // still 2 cm in the air
  EXPECT_EQ(length(world.info(0).contactForce), 0.0f);
  EXPECT_EQ(length(world.info(1).contactForce), 0.0f);
  for (int step = 0; step < 1500; ++step) world.step(1e-3, {});
  const ObjectInfo before = world.info(1);
  double impulse = 0.0, largestImbalance = 0.0;
  constexpr int kSteps = 500;
  constexpr double kDt = 1e-3;
  for (int step = 0; step < kSteps; ++step) {
    world.step(kDt, {});
    impulse += world.contactForce(1).y * kDt;
    largestImbalance =
        std::max(largestImbalance, double(length(world.contactForce(0) + world.contactForce(1))));
  }
  const ObjectInfo after = world.info(1);
  const double weight = before.mass * 9.81, duration = kSteps * kDt;
  const double momentumChange = before.mass * (double(after.velocity.y) - before.velocity.y);
  EXPECT_NEAR(impulse - weight * duration, momentumChange, 0.005 * weight * duration);
  EXPECT_NEAR(impulse / duration, weight, 0.02 * weight);  // nearly at rest
  EXPECT_LT(largestImbalance, 1e-4 * weight);
  EXPECT_NEAR(world.info(0).startCentre.y, -0.04, 1e-6);
}

// The plate squeezing the tube is pushed back up, harder the deeper it goes, and the tube
// feels the opposite.
TEST(ObjectWorld, AClampFeelsTheTubeItSqueezes) {
  ObjectWorld world(clampOnTube(), clampSettings());
  double at40ms = 0.0;
  for (int ms = 1; ms <= 100; ++ms) {
    world.step(1e-3, {});
    const Vec3 onClamp = world.contactForce(1);
    EXPECT_NEAR(world.contactForce(0).y, -onClamp.y, 1e-4 * std::abs(onClamp.y) + 1e-9);
    if (ms == 40) at40ms = onClamp.y;
  }
  EXPECT_GT(at40ms, 0.0);
  EXPECT_GT(world.contactForce(1).y, 3.0 * at40ms);  // measured 0.059 N against 0.009 N
}

TEST(ObjectWorld, SubstepsResolveTheStiffestSpring) {
  ObjectDesc d = tube({0, 0, 0}, 0.01, 0.04, 0.0025);
  d.deformable.stiffness = 100.0;
  const ObjectWorld world({d}, settings());
  const double m = world.particles().mass[0];
  const double omega = std::sqrt(100.0 / (0.5 * m));
  // Critical damping: c / m_red = 2 ω; the damping bound 0.25 / (2 ω) is the tighter one.
  EXPECT_NEAR(world.stableSubstep(), std::min(0.3 / omega, 0.125 / omega), 1e-12);
  const ObjectWorld lonely({box({0, 0, 0}, {0.1, 0.1, 0.1}, 0.01)}, settings());
  EXPECT_TRUE(std::isinf(lonely.stableSubstep()));
}

// A ball falling fast far below two resting boxes: inside the region its speed bounds the
// substep (no particle travels more than a quarter of its radius in one); past it, not.
TEST(ObjectWorld, AParticleOutsideTheRegionBoundsNoSubstep) {
  ObjectDesc ball = sphere({0, -5, 0}, 0.02, 0.01);
  ball.name = "ball";
  ball.velocity = {0, -50, 0};
  ObjectDesc left = box({0, 0, 0}, {0.05, 0.05, 0.05}, 0.01);
  left.name = "left";
  ObjectDesc right = box({0.2, 0, 0}, {0.05, 0.05, 0.05}, 0.01);
  right.name = "right";
  const std::vector<ObjectDesc> objects = {left, right, ball};
  WorldSettings s = settings({0, -9.81f, 0});
  s.contact = {50.0f, 0.005f, 0.0f};
  const ObjectWorld everywhere(objects, s);
  s.regionMin = {-1, -1, -1};
  s.regionMax = {1, 1, 1};
  const ObjectWorld region(objects, s);
  const double radius = 0.5 * 0.01;
  EXPECT_LE(everywhere.stableSubstep(), 0.25 * radius / 50.0 * 1.000001);
  EXPECT_GT(region.stableSubstep(), 10.0 * everywhere.stableSubstep());
}

std::vector<ObjectDesc> busyScene() {
  std::vector<ObjectDesc> objects = clampOnTube();
  ObjectDesc ball = sphere({0.025, 0.03, 0.0}, 0.008, 0.0025);
  ball.velocity = {0, -0.5, 0.1};
  ball.angularVelocity = {1, 2, 3};
  objects.push_back(ball);
  objects[0].deformable.breakingStrain = 0.05;
  return objects;
}

TEST(ObjectWorld, SameStepsGiveBitIdenticalParticles) {
  WorldSettings s = clampSettings();
  s.gravity = {0, -9.81f, 0};
  ObjectWorld a(busyScene(), s), b(busyScene(), s);
  std::vector<Vec3> force(a.particles().size(), Vec3{0, 0, 0});
  for (int step = 0; step < 100; ++step) {
    force[step % force.size()] = {0.01f, 0, 0};
    a.step(1e-3, force);
    b.step(1e-3, force);
  }
  test::expectSameBytes(a.particles(), b.particles());
  // And the scene did something: the ball moved and hit the tube.
  EXPECT_LT(a.info(2).centreOfMass.y, 0.03f - 0.01f);
}

// Builds the one object and returns the InputError's message ("" if none).
std::string errorOf(const ObjectDesc& d) {
  try {
    ObjectWorld world({box({5, 5, 5}, {0.1, 0.1, 0.1}, 0.01), d}, settings());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ObjectWorld, ImpossibleGeometryIsAnInputErrorNamingTheKey) {
  ObjectDesc pointSphere = sphere({0, 0, 0}, 0.0, 0.01);
  pointSphere.shape.radius = 0.0;
  EXPECT_EQ(errorOf(pointSphere),
            "scene.json: objects[1].shape.radius: expected a positive number, got 0");
  // A solid body's particles lie half a spacing inside its surface: it must be thicker.
  pointSphere.shape.radius = 0.004;
  EXPECT_EQ(errorOf(pointSphere),
            "scene.json: objects[1].shape.radius: a solid body's particles lie half a spacing "
            "(0.005 m) inside its surface; expected more than 0.005, got 0.004");
  EXPECT_NE(errorOf(box({0, 0, 0}, {0.1, -0.1, 0.1}, 0.01)).find("objects[1].shape.half_extents"),
            std::string::npos);
  EXPECT_NE(errorOf(tube({0, 0, 0}, 0.003, 0.1, 0.01)).find("objects[1].shape.radius"),
            std::string::npos);  // 2π·0.3 ≈ 1.9 particles around
  EXPECT_NE(errorOf(tube({0, 0, 0}, 0.02, 0.0, 0.01)).find("objects[1].shape.length"),
            std::string::npos);
  ObjectDesc noAxis = tube({0, 0, 0}, 0.02, 0.1, 0.01);
  noAxis.shape.axis = {0, 0, 0};
  EXPECT_NE(errorOf(noAxis).find("objects[1].shape.axis"), std::string::npos);
  ObjectDesc mesh;
  mesh.shape.kind = ShapeKind::Mesh;
  mesh.shape.meshFile = "no_such_mesh.obj";
  const std::string missing = errorOf(mesh);
  EXPECT_NE(missing.find("objects[1].shape.file"), std::string::npos) << missing;
  EXPECT_NE(missing.find("no_such_mesh.obj"), std::string::npos) << missing;
  ObjectDesc light = sphere({0, 0, 0}, 0.05, 0.01);
  light.density = 0.0;
  EXPECT_NE(errorOf(light).find("objects[1].density"), std::string::npos);
  ObjectDesc negative = sphere({0, 0, 0}, 0.05, -0.01);
  EXPECT_NE(errorOf(negative).find("objects[1].spacing"), std::string::npos);
  ObjectDesc layers = sphere({0, 0, 0}, 0.05, 0.01);
  layers.shape.layers = 0;
  EXPECT_NE(errorOf(layers).find("objects[1].shape.layers"), std::string::npos);
  ObjectDesc reach = tube({0, 0, 0}, 0.02, 0.1, 0.01);
  for (double bad : {0.9, 1.0, 3.5}) {
    reach.deformable.springReach = bad;
    EXPECT_NE(
        errorOf(reach).find("objects[1].deformable.spring_reach: expected a number in (1, 3]"),
        std::string::npos)
        << bad;
  }
  ObjectDesc keys = box({0, 0, 0}, {0.1, 0.1, 0.1}, 0.01, ObjectMotion::Kinematic);
  keys.keyframes = {{0.5, {}, {}}, {0.5, {}, {}}};
  EXPECT_NE(errorOf(keys).find("objects[1].keyframes[1].time"), std::string::npos);
  EXPECT_EQ(errorOf(sphere({0, 0, 0}, 0.05, 0.01)), "");
}

}  // namespace
}  // namespace sph::objects
