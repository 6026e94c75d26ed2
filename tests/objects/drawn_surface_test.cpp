// The surfaces objects are drawn with (src/objects/drawn_surface.*, sph/object_surface.hpp):
// closed and wound outward where the shape is closed, enclosing the shape's volume; at rest on
// their particles; carried rigidly by a rigid motion; opened along a cut and nowhere else.
#include "objects/drawn_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "drawn_surface_frames.hpp"
#include "object_scenes.hpp"
#include "objects/axis_box.hpp"
#include "objects/object_world.hpp"
#include "sph/core/constants.hpp"
#include "sph/object_surface.hpp"
#include "sph/scene_file.hpp"
#include "sph/simulation.hpp"

namespace sph::objects {
namespace {

constexpr double kSpacing = 0.002;

using test::frameOf;
using test::meshOf;

// Directed edges: a closed surface wound one way has each edge once in each direction.
struct EdgeCount {
  std::size_t unpaired = 0;  // an edge without its reverse: an open rim or a flipped triangle
  std::size_t repeated = 0;  // a directed edge used twice: non-manifold or misoriented
};

EdgeCount countEdges(const DrawnSurface& d) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : d.triangles)
    for (int c = 0; c < 3; ++c) ++directed[{t[c], t[(c + 1) % 3]}];
  EdgeCount out;
  for (const auto& [edge, count] : directed) {
    if (count > 1) ++out.repeated;
    if (!directed.count({edge.second, edge.first})) ++out.unpaired;
  }
  return out;
}

double signedVolume(const DrawnSurface& d) {
  double v = 0.0;
  for (const auto& t : d.triangles)
    v += dot(d.vertex[t[0]], cross(d.vertex[t[1]], d.vertex[t[2]])) / 6.0;
  return v;
}

ObjectDesc capsule(Vec3d center, double radius, double length) {
  ObjectDesc d;
  d.name = "capsule";
  d.shape.kind = ShapeKind::Capsule;
  d.shape.center = center;
  d.shape.radius = radius;
  d.shape.length = length;
  d.shape.axis = {1, 1, 0};
  d.spacing = kSpacing;
  return d;
}

struct ClosedCase {
  const char* name;
  ObjectDesc desc;
  double volume;  // of the surface drawn
};

std::vector<ClosedCase> closedCases() {
  const double r = 0.012, length = 0.03;
  ObjectDesc box;
  box.name = "box";
  box.shape.kind = ShapeKind::Box;
  box.shape.center = {0.1, 0.05, 0};
  box.shape.halfExtents = {0.02, 0.011, 0.015};
  box.spacing = kSpacing;
  ObjectDesc ball;
  ball.name = "ball";
  ball.shape.kind = ShapeKind::Sphere;
  ball.shape.center = {0, 0.2, 0};
  ball.shape.radius = r;
  ball.spacing = kSpacing;
  ObjectDesc tube = test::tube({0, 0, 0}, r, length, kSpacing);
  tube.shape.layers = 2;
  // A capped tube is drawn at its wall's outer face: half a spacing beyond its particles.
  const double outer = r + 0.5 * kSpacing;
  return {{"box", box, 8 * 0.02 * 0.011 * 0.015},
          {"sphere", ball, 4.0 / 3.0 * kPi * r * r * r},
          {"capsule", capsule({0, 0, 0.1}, r, length),
           kPi * r * r * length + 4.0 / 3.0 * kPi * r * r * r},
          {"capped tube", tube, kPi * outer * outer * (length + kSpacing)}};
}

TEST(DrawnSurface, ClosedShapesAreClosedAndWoundOutward) {
  for (const ClosedCase& c : closedCases()) {
    SCOPED_TRACE(c.name);
    const ObjectWorld world({c.desc}, test::settings());
    const DrawnSurface& d = world.drawnSurface(0);
    ASSERT_GT(d.triangles.size(), 100u);
    const EdgeCount edges = countEdges(d);
    EXPECT_EQ(edges.unpaired, 0u);
    EXPECT_EQ(edges.repeated, 0u);
    // Positive: wound outward. Within 3 %: a polyhedron at the particle spacing.
    EXPECT_NEAR(signedVolume(d) / c.volume, 1.0, 0.03);
  }
}

TEST(DrawnSurface, AnOpenTubeIsOpenAtItsEndsOnly) {
  ObjectDesc d = test::tube({0, 0, 0}, 0.01, 0.03, kSpacing);
  d.shape.capped = false;
  const ObjectWorld world({d}, test::settings());
  const DrawnSurface& s = world.drawnSurface(0);
  const int around = int(std::lround(2.0 * kPi * 0.01 / kSpacing));
  const EdgeCount edges = countEdges(s);
  EXPECT_EQ(edges.unpaired, std::size_t(2 * around));  // the two end rings
  EXPECT_EQ(edges.repeated, 0u);
  for (std::size_t v = 0; v < s.vertex.size(); ++v)
    EXPECT_LT(std::abs(s.vertex[v].x), 0.015 + 1e-9);
}

TEST(DrawnSurface, ATubeIsDrawnOverItsOuterLayer) {
  ObjectDesc d = test::tube({0, 0, 0}, 0.01, 0.03, kSpacing);
  d.shape.layers = 2;
  const ObjectWorld world({d}, test::settings());
  const ParticleState& p = world.particles();
  const DrawnSurface& s = world.drawnSurface(0);
  std::size_t outer = 0;
  for (std::uint8_t flag : p.surface) outer += flag;
  EXPECT_EQ(s.vertex.size(), outer);
  for (std::size_t v = 0; v < s.vertex.size(); ++v) {
    const std::uint32_t k = s.anchor[v][0];
    EXPECT_EQ(p.surface[k], 1);
    // Half a spacing out along the particle's normal.
    const DVec3 offset = s.vertex[v] - toD(p.position[k]);
    EXPECT_NEAR(norm(offset), 0.5 * kSpacing, 1e-6);
    EXPECT_GT(dot(offset, toD(p.normal[k])), 0.499 * kSpacing);
  }
}

// Every vertex back where it was built, from its particles.
TEST(DrawnSurface, VerticesSitOnTheirParticlesAtRest) {
  for (const ClosedCase& c : closedCases()) {
    SCOPED_TRACE(c.name);
    const ObjectWorld world({c.desc}, test::settings());
    const DrawnSurface& d = world.drawnSurface(0);
    const PlacedSurface placed = placeObjectSurface(meshOf(d), frameOf(world.particles()));
    for (std::size_t v = 0; v < d.vertex.size(); ++v)
      for (int a = 0; a < 3; ++a)
        ASSERT_NEAR(placed.position[3 * v + a], (&d.vertex[v].x)[a], 1e-6) << "vertex " << v;
    EXPECT_EQ(std::count(placed.open.begin(), placed.open.end(), 1), 0);
  }
}

TEST(DrawnSurface, ARigidMotionCarriesTheSurfaceRigidly) {
  for (const ClosedCase& c : closedCases()) {
    SCOPED_TRACE(c.name);
    const ObjectWorld world({c.desc}, test::settings());
    const DrawnSurface& d = world.drawnSurface(0);
    ParticleFrame frame = frameOf(world.particles());
    const Mat3 turn = rotationFromVector({0.3, -0.7, 1.1});
    const DVec3 shift{0.05, -0.02, 0.3};
    const auto move = [&](DVec3 x) { return turn * x + shift; };
    for (std::size_t k = 0; k < frame.size(); ++k) {
      const DVec3 x =
          move({frame.position[3 * k], frame.position[3 * k + 1], frame.position[3 * k + 2]});
      frame.position[3 * k] = float(x.x);
      frame.position[3 * k + 1] = float(x.y);
      frame.position[3 * k + 2] = float(x.z);
    }
    const PlacedSurface placed = placeObjectSurface(meshOf(d), frame);
    for (std::size_t v = 0; v < d.vertex.size(); ++v) {
      const DVec3 expected = move(d.vertex[v]);
      for (int a = 0; a < 3; ++a)
        ASSERT_NEAR(placed.position[3 * v + a], (&expected.x)[a], 2e-6) << "vertex " << v;
    }
  }
}

// The slit of a cut is a hole in the surface: every triangle across it is open, and the open
// ones keep to the cut's neighbourhood.
TEST(DrawnSurface, ACutOpensTheSurfaceAlongIt) {
  ObjectDesc d = test::tube({0, 0, 0}, 0.006, 0.03, 0.001);
  d.deformable.model = DeformableModel::Xpbd;
  d.deformable.springReach = 2.2;
  const AxisBox cut{{-0.004, -0.007, -0.00015}, {0.004, -0.005, 0.00015}};
  d.deformable.cuts = {cut};
  const ObjectWorld world({d}, test::settings());
  const ParticleState& p = world.particles();
  const DrawnSurface& s = world.drawnSurface(0);
  const PlacedSurface placed = placeObjectSurface(meshOf(s), frameOf(p));

  std::size_t open = 0, across = 0;
  const double reach = 2.2 * 0.001;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tri = s.triangles[t];
    bool crosses = false;
    for (int c = 0; c < 3; ++c) {
      const Vec3 a = p.position[s.anchor[tri[c]][0]], b = p.position[s.anchor[tri[(c + 1) % 3]][0]];
      crosses = crosses || segmentMeetsBox(cut, toD(a), toD(b));
    }
    across += crosses;
    if (crosses) {
      EXPECT_TRUE(placed.open[t]) << "triangle " << t << " spans the cut but is drawn";
    }
    if (!placed.open[t]) continue;
    ++open;
    for (std::uint32_t v : tri) {
      const Vec3 x = p.position[s.anchor[v][0]];
      for (int c = 0; c < 3; ++c) {
        EXPECT_GT((&x.x)[c], cut.min[c] - reach);
        EXPECT_LT((&x.x)[c], cut.max[c] + reach);
      }
    }
  }
  EXPECT_GT(across, 10u);
  EXPECT_GE(open, across);
  EXPECT_LT(open, s.triangles.size() / 20);
}

// Through the Simulation: the anchors are the frame's particle ids.
TEST(DrawnSurface, SimulationGivesSurfacesOnItsFrameIds) {
  const Scene scene = sph::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/artery_tear.json");
  const Simulation sim(scene);
  const std::vector<ObjectSurfaceMesh> surfaces = sim.objectSurfaces();
  ASSERT_EQ(surfaces.size(), scene.objects.size());
  const ParticleFrame frame = sim.frame();
  for (const ObjectSurfaceMesh& mesh : surfaces) {
    SCOPED_TRACE(scene.objects[mesh.object].name);
    const PlacedSurface placed = placeObjectSurface(mesh, frame);
    for (std::size_t i = 0; i < mesh.restPosition.size(); ++i)
      ASSERT_NEAR(placed.position[i], mesh.restPosition[i], 1e-6);
    const auto open = std::count(placed.open.begin(), placed.open.end(), 1);
    // The artery's cut is open from the start; the clamps never tear.
    if (scene.objects[mesh.object].deformable.cuts.empty())
      EXPECT_EQ(open, 0);
    else
      EXPECT_GT(open, 0);
  }
}

}  // namespace
}  // namespace sph::objects
