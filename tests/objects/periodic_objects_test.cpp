// Objects in a domain with periodic axes: a collision across a periodic face is the collision
// the same two objects have in the middle of the domain, and an object that leaves through a
// face comes back whole through the other.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "object_scenes.hpp"
#include "objects/periodic_space.hpp"

namespace sph::objects {
namespace {

using test::sphere;

// Periodic along x over [-0.1, 0.1): a period of 0.2 m.
PeriodicSpace periodicX() {
  PeriodicSpace space;
  space.periodic[0] = true;
  space.lo = {-0.1, -1.0, -1.0};
  space.length = {0.2, 0.0, 0.0};
  return space;
}

TEST(PeriodicSpace, TakesSeparationsToTheNearestImageAndPositionsIntoThePeriod) {
  const PeriodicSpace space = periodicX();
  const DVec3 d = space.nearest(DVec3{0.15, 0.3, -0.7});
  EXPECT_NEAR(d.x, -0.05, 1e-12);
  EXPECT_EQ(d.y, 0.3);  // not periodic: as it was
  EXPECT_EQ(d.z, -0.7);
  EXPECT_NEAR(space.nearest(DVec3{-0.43, 0, 0}).x, -0.03, 1e-12);  // two periods away
  EXPECT_NEAR(space.wrapped(DVec3{0.13, 5, 0}).x, -0.07, 1e-12);
  EXPECT_NEAR(space.wrapped(DVec3{-0.35, 0, 0}).x, 0.05, 1e-12);
  EXPECT_EQ(space.wrapped(DVec3{0.02, 0, 0}).x, 0.02);  // inside: untouched
  EXPECT_NEAR(space.shiftInto(DVec3{0.11, 0, 0}).x, -0.2, 1e-12);

  std::vector<double> shifts;
  space.forEachImage(DVec3{-0.095, 0, 0}, 0.01, [&](DVec3 s) { shifts.push_back(s.x); });
  EXPECT_EQ(shifts, (std::vector<double>{0.0, 0.2}));
  shifts.clear();
  space.forEachImage(DVec3{0.0, 0, 0}, 0.01, [&](DVec3 s) { shifts.push_back(s.x); });
  EXPECT_EQ(shifts, (std::vector<double>{0.0}));
}

WorldSettings contactSettings(bool periodic) {
  WorldSettings s = test::settings();
  s.contact = {500.0f, 0.05f, 0.01f};
  if (periodic) {
    s.periodic = periodicX();
    s.regionMin = {-3.0e38f, -1.0f, -1.0f};
    s.regionMax = {3.0e38f, 1.0f, 1.0f};
  }
  return s;
}

struct Collision {
  std::vector<Vec3> velocity;  // of each body after it
  std::vector<double> centreX;
  bool wrapped = false;  // a centre jumped by a period in a step
  double largestMomentum = 0.0;
};

// Two bodies 4 cm across, 0.1 m apart centre to centre, closing at 0.5 m/s: they meet after
// 0.12 s. `at` places their midpoint; both bodies of `motion`.
Collision collide(double at, bool periodic, ObjectMotion motion) {
  ObjectDesc a = sphere({at - 0.05, 0, 0}, 0.02, 0.01, motion);
  ObjectDesc b = sphere({at + 0.05, 0.004, 0}, 0.02, 0.01, motion);
  a.velocity = {0.25, 0, 0};
  b.velocity = {-0.25, 0, 0};
  a.deformable.model = b.deformable.model = DeformableModel::Xpbd;
  ObjectWorld world({a, b}, contactSettings(periodic));
  Collision c;
  double previous[2] = {world.info(0).centreOfMass.x, world.info(1).centreOfMass.x};
  for (int step = 0; step < 250; ++step) {
    world.step(1e-3, {});
    double momentum = 0.0;
    for (int o = 0; o < 2; ++o) {
      const ObjectInfo info = world.info(std::size_t(o));
      momentum += info.mass * info.velocity.x;
      c.wrapped = c.wrapped || std::abs(info.centreOfMass.x - previous[o]) > 0.1;
      previous[o] = info.centreOfMass.x;
      if (periodic) {
        EXPECT_GE(info.centreOfMass.x, -0.1f);
        EXPECT_LT(info.centreOfMass.x, 0.1f);
      }
    }
    c.largestMomentum = std::max(c.largestMomentum, std::abs(momentum));
  }
  for (int o = 0; o < 2; ++o) {
    c.velocity.push_back(world.info(std::size_t(o)).velocity);
    c.centreX.push_back(world.info(std::size_t(o)).centreOfMass.x);
  }
  return c;
}

// `tolerance`: of the velocities (m/s); of the positions, a tenth of it (m).
void expectSameCollision(ObjectMotion motion, double tolerance) {
  // Met at the face x = ±0.1, through each other's images; and the same in the middle of a
  // world with no periodic axes.
  const Collision atFace = collide(0.1, true, motion);
  const Collision inMiddle = collide(0.0, false, motion);
  EXPECT_TRUE(atFace.wrapped);  // the body that started past the face came back into it
  for (int o = 0; o < 2; ++o) {
    // They did collide: each bounced back, as in the middle.
    EXPECT_LT(inMiddle.velocity[o].x * (o == 0 ? 1 : -1), 0.0f) << "body " << o;
    EXPECT_LT(length(atFace.velocity[o] - inMiddle.velocity[o]), tolerance) << "body " << o;
    // Where each ended, a period apart or not at all.
    const double apart = atFace.centreX[o] - (inMiddle.centreX[o] + 0.1);
    EXPECT_NEAR(apart - 0.2 * std::round(apart / 0.2), 0.0, 0.1 * tolerance) << "body " << o;
  }
  EXPECT_LT(atFace.largestMomentum, 1e-9);  // equal masses, opposite velocities throughout
}

TEST(PeriodicObjects, RigidBodiesCollideAcrossAFaceAsInTheMiddle) {
  expectSameCollision(ObjectMotion::Rigid, 1e-6);  // the same forces, rounded alike
}

// XPBD deformables meet by contact constraints; their springs must not span the face, so each
// is moved whole. The constraints are projected one after another, in the order the search
// finds the pairs, which the face changes: measured 2.8e-5 m/s apart of the 0.5 m/s they met
// at, where passing through each other would leave them 0.5 m/s apart.
TEST(PeriodicObjects, XpbdDeformablesCollideAcrossAFaceAsInTheMiddle) {
  expectSameCollision(ObjectMotion::Deformable, 2e-4);
}

// A deformable drifting through a face many times is never torn apart by it: its particles
// keep their distances.
TEST(PeriodicObjects, ADeformableCrossesTheFaceWhole) {
  ObjectDesc d = sphere({0.08, 0, 0}, 0.03, 0.01, ObjectMotion::Deformable);
  d.deformable.model = DeformableModel::Xpbd;
  d.velocity = {2.0, 0, 0};
  ObjectWorld world({d}, contactSettings(true));
  const ParticleState& p = world.particles();
  const std::vector<Vec3> start = p.position;
  double travelled = 0.0, previous = world.info(0).centreOfMass.x;
  for (int step = 0; step < 500; ++step) {
    world.step(1e-3, {});
    const double x = world.info(0).centreOfMass.x;
    travelled += periodicX().nearest(DVec3{x - previous, 0, 0}).x;
    previous = x;
  }
  EXPECT_NEAR(travelled, 1.0, 1e-3);  // five periods
  double largestChange = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i)
    largestChange =
        std::max(largestChange, std::abs(double(test::distance(p.position[i], p.position[0])) -
                                         double(test::distance(start[i], start[0]))));
  EXPECT_LT(largestChange, 1e-5);
}

}  // namespace
}  // namespace sph::objects
