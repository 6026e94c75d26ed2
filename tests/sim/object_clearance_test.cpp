// Clearing the fluid's initial lattice around objects (src/sim/object_clearance.cpp): a fluid
// particle that starts within contact reach of an object particle would be thrown off by the
// first contact forces, and one in the cavity of a closed body would ride inside it as trapped
// weight, unless that body is the vessel the block fills. Each relation is checked against a
// search of every object particle, the nearest periodic image included.
#include "sim/object_clearance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "objects/math3d.hpp"
#include "sim/sampling.hpp"

namespace sph {
namespace {

constexpr double kSpacing = 0.01;

// The fluid's radius plus the influence sphere of 1.5 object radii (Meteer 2011, §8.2).
float reach(float objectRadius) {
  return 0.5f * float(kSpacing) + 1.5f * objectRadius;
}

objects::WorldSettings settings() {
  objects::WorldSettings s;
  s.defaultSpacing = float(kSpacing);
  s.sourceName = "clearance.json";
  return s;
}

// A hollow ball whose particle layer lies `radius` from its centre.
ObjectDesc hollowBall(Vec3d centre, double radius = 0.03) {
  ObjectDesc d;
  d.name = "ball";
  d.shape.kind = ShapeKind::Sphere;
  d.shape.center = centre;
  d.shape.radius = radius + 0.5 * kSpacing;  // a rigid body's particles lie half a spacing in
  d.spacing = kSpacing;
  return d;
}

bool nearAnObjectParticle(const objects::ObjectWorld& world, Vec3 p) {
  const objects::ParticleState& particles = world.particles();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const objects::DVec3 offset =
        world.periodicSpace().nearest(objects::toD(particles.position[i]) - objects::toD(p));
    if (objects::norm(offset) < reach(particles.radius[i])) return true;
  }
  return false;
}

bool inACavity(const objects::ObjectWorld& world, Vec3 p, int container) {
  const objects::PeriodicSpace& space = world.periodicSpace();
  for (std::size_t o = 0; o < world.objectCount(); ++o) {
    if (int(o) == container) continue;
    for (int k = -1; k <= 1; ++k) {
      if (k != 0 && !space.periodic[0]) continue;
      const Vec3 image{p.x + float(k * space.length.x), p.y, p.z};
      if (world.interiorContains(o, image, 0.0f)) return true;
    }
  }
  return false;
}

std::vector<Vec3> cleared(std::vector<Vec3> points, const objects::ObjectWorld& world,
                          int container) {
  sim::removeObjectOverlap(points, world, reach, container);
  return points;
}

// What should remain, in the lattice's order, and how many points each reason removes.
struct Expected {
  std::vector<Vec3> kept;
  std::size_t near = 0, cavityOnly = 0;
};

Expected expected(const std::vector<Vec3>& points, const objects::ObjectWorld& world,
                  int container) {
  Expected e;
  for (const Vec3& p : points) {
    if (nearAnObjectParticle(world, p))
      ++e.near;
    else if (inACavity(world, p, container))
      ++e.cavityOnly;
    else
      e.kept.push_back(p);
  }
  return e;
}

void expectSamePoints(const std::vector<Vec3>& got, const std::vector<Vec3>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].x, want[i].x) << "point " << i;
    EXPECT_EQ(got[i].y, want[i].y) << "point " << i;
    EXPECT_EQ(got[i].z, want[i].z) << "point " << i;
  }
}

TEST(ObjectClearance, RemovesThePointsWithinReachAndInTheCavityKeepingTheOrder) {
  const objects::ObjectWorld world({hollowBall({0.1, 0.1, 0.1})}, settings());
  const std::vector<Vec3> lattice =
      sim::sampleBlock({{0.05, 0.05, 0.05}, {0.15, 0.15, 0.15}}, kSpacing);
  const Expected want = expected(lattice, world, -1);
  EXPECT_GT(want.near, 0u);
  EXPECT_GT(want.cavityOnly, 0u);
  EXPECT_GT(want.kept.size(), 0u);
  expectSamePoints(cleared(lattice, world, -1), want.kept);
}

TEST(ObjectClearance, KeepsTheCavityOfTheContainer) {
  const objects::ObjectWorld world({hollowBall({0.1, 0.1, 0.1})}, settings());
  const std::vector<Vec3> lattice =
      sim::sampleBlock({{0.05, 0.05, 0.05}, {0.15, 0.15, 0.15}}, kSpacing);
  const Expected want = expected(lattice, world, 0);
  EXPECT_EQ(want.cavityOnly, 0u);
  const std::vector<Vec3> got = cleared(lattice, world, 0);
  expectSamePoints(got, want.kept);
  std::size_t inside = 0;
  for (const Vec3& p : got) inside += world.interiorContains(0, p, 0.0f) ? 1 : 0;
  EXPECT_GT(inside, 0u);
  // Another closed body's cavity is still cleared.
  const objects::ObjectWorld two({hollowBall({0.1, 0.1, 0.1}), hollowBall({0.3, 0.1, 0.1})},
                                 settings());
  const std::vector<Vec3> both =
      sim::sampleBlock({{0.05, 0.05, 0.05}, {0.35, 0.15, 0.15}}, kSpacing);
  const Expected wantBoth = expected(both, two, 1);
  EXPECT_GT(wantBoth.cavityOnly, 0u);
  expectSamePoints(cleared(both, two, 1), wantBoth.kept);
}

TEST(ObjectClearance, AnOpenBodyHasNoCavityToClear) {
  ObjectDesc pipe;
  pipe.name = "pipe";
  pipe.shape.kind = ShapeKind::Tube;
  pipe.shape.center = {0.1, 0.1, 0.1};
  pipe.shape.radius = 0.03;
  pipe.shape.length = 0.06;
  pipe.shape.axis = {1, 0, 0};
  pipe.shape.capped = false;
  pipe.spacing = kSpacing;
  const objects::ObjectWorld world({pipe}, settings());
  ASSERT_FALSE(world.enclosesVolume(0));
  const std::vector<Vec3> lattice =
      sim::sampleBlock({{0.06, 0.06, 0.06}, {0.14, 0.14, 0.14}}, kSpacing);
  const Expected want = expected(lattice, world, -1);
  const std::vector<Vec3> got = cleared(lattice, world, -1);
  expectSamePoints(got, want.kept);
  std::size_t inTheBore = 0;
  for (const Vec3& p : got)
    inTheBore += std::hypot(p.y - 0.1, p.z - 0.1) < 0.02 && std::abs(p.x - 0.1) < 0.03 ? 1 : 0;
  EXPECT_GT(inTheBore, 0u);
}

TEST(ObjectClearance, AnObjectClearsThroughAPeriodicFace) {
  objects::WorldSettings s = settings();
  s.periodic.periodic[0] = true;
  s.periodic.lo = objects::DVec3{0.0, 0.0, 0.0};
  s.periodic.length = objects::DVec3{0.2, 0.0, 0.0};
  // Its particles end 5 mm inside the upper face: only its image reaches in through the lower
  // one.
  const objects::ObjectWorld world({hollowBall({0.175, 0.1, 0.1}, 0.02)}, s);
  const std::vector<Vec3> lattice =
      sim::sampleBlock({{0.0, 0.05, 0.05}, {0.2, 0.15, 0.15}}, kSpacing);
  const Expected want = expected(lattice, world, -1);
  const std::vector<Vec3> got = cleared(lattice, world, -1);
  expectSamePoints(got, want.kept);
  std::size_t goneNearTheLowerFace = 0;
  for (const Vec3& p : lattice) {
    if (p.x > 0.05f) continue;
    bool kept = false;
    for (const Vec3& q : got) kept = kept || (q.x == p.x && q.y == p.y && q.z == p.z);
    goneNearTheLowerFace += kept ? 0 : 1;
  }
  EXPECT_GT(goneNearTheLowerFace, 0u);
}

TEST(ObjectClearance, WithoutObjectsNothingIsRemoved) {
  const objects::ObjectWorld world({}, settings());
  const std::vector<Vec3> lattice = sim::sampleBlock({{0, 0, 0}, {0.05, 0.05, 0.05}}, kSpacing);
  expectSamePoints(cleared(lattice, world, -1), lattice);
}

}  // namespace
}  // namespace sph
