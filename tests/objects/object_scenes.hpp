// Object descriptions shared by the object engine tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "objects/object_world.hpp"

namespace sph::objects::test {

// A solid (rigid or kinematic) body's particles lie half a spacing inside its described
// surface. The tests place bodies by their particle layer: `box` and `sphere` describe the
// shape whose outer particles lie at `halfExtents` / `radius`.
inline double insetOf(ObjectMotion motion, double spacing) {
  return motion == ObjectMotion::Deformable ? 0.0 : 0.5 * spacing;
}

inline ObjectDesc box(Vec3d center, Vec3d halfExtents, double spacing,
                      ObjectMotion motion = ObjectMotion::Rigid) {
  ObjectDesc d;
  d.name = "box";
  d.motion = motion;
  d.shape.kind = ShapeKind::Box;
  d.shape.center = center;
  const double inset = insetOf(motion, spacing > 0.0 ? spacing : 0.01);
  d.shape.halfExtents = {halfExtents[0] + inset, halfExtents[1] + inset, halfExtents[2] + inset};
  d.spacing = spacing;
  return d;
}

inline ObjectDesc sphere(Vec3d center, double radius, double spacing,
                         ObjectMotion motion = ObjectMotion::Rigid) {
  ObjectDesc d;
  d.name = "sphere";
  d.motion = motion;
  d.shape.kind = ShapeKind::Sphere;
  d.shape.center = center;
  d.shape.radius = radius + insetOf(motion, spacing > 0.0 ? spacing : 0.01);
  d.spacing = spacing;
  return d;
}

inline ObjectDesc tube(Vec3d center, double radius, double length, double spacing,
                       ObjectMotion motion = ObjectMotion::Deformable) {
  ObjectDesc d;
  d.name = "tube";
  d.motion = motion;
  d.shape.kind = ShapeKind::Tube;
  d.shape.center = center;
  d.shape.radius = radius;
  d.shape.length = length;
  d.shape.axis = {1, 0, 0};
  d.spacing = spacing;
  return d;
}

inline WorldSettings settings(Vec3 gravity = {0, 0, 0}) {
  WorldSettings s;
  s.gravity = gravity;
  s.defaultSpacing = 0.01f;
  s.sourceName = "scene.json";
  return s;
}

// Two worlds run alike: every particle's position, velocity and normal bit for bit, and its cuts.
inline void expectSameBytes(const ParticleState& a, const ParticleState& b) {
  ASSERT_EQ(a.size(), b.size());
  const std::size_t bytes = a.size() * sizeof(Vec3);
  EXPECT_EQ(std::memcmp(a.position.data(), b.position.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(a.velocity.data(), b.velocity.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(a.normal.data(), b.normal.data(), bytes), 0);
  EXPECT_EQ(a.cut, b.cut);
}

inline double distance(Vec3 a, Vec3 b) {
  return length(a - b);
}

// Distance from particle i to its nearest neighbour among the particles [first, end).
inline double nearestNeighbour(const std::vector<Vec3>& p, std::size_t i) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < p.size(); ++j)
    if (j != i) best = std::min(best, distance(p[i], p[j]));
  return best;
}

}  // namespace sph::objects::test
