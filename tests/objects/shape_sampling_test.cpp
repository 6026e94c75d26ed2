// Sampling of primitive shapes into object particles (src/objects/shape_sampling.*), seen
// through ObjectWorld: counts, spacing, outward unit normals, surface flags, masses, and the
// interior test on the shape as built.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "object_scenes.hpp"
#include "sph/core/constants.hpp"
#include "sph/error.hpp"

namespace sph::objects {
namespace {

using test::box;
using test::nearestNeighbour;
using test::settings;
using test::sphere;
using test::tube;

void expectUnitOutwardNormals(const ParticleState& p, Vec3 centre) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(length(p.normal[i]), 1.0, 1e-5) << "particle " << i;
    EXPECT_GT(dot(p.normal[i], p.position[i] - centre), 0.0f) << "particle " << i;
  }
}

TEST(ShapeSampling, HollowBoxLiesOnItsFacesAtTheSpacing) {
  const ObjectWorld world({box({0.5, 0.2, 0.1}, {0.1, 0.05, 0.02}, 0.01)}, settings());
  const ParticleState& p = world.particles();
  // Lattice of 20 × 10 × 4 intervals: 21·11·5 points less the 19·9·3 inside.
  ASSERT_EQ(p.size(), 21u * 11u * 5u - 19u * 9u * 3u);
  const Vec3 c{0.5f, 0.2f, 0.1f};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 d = p.position[i] - c;
    const double onFace =
        std::max({std::abs(d.x) / 0.1, std::abs(d.y) / 0.05, std::abs(d.z) / 0.02});
    EXPECT_NEAR(onFace, 1.0, 1e-5);
    EXPECT_NEAR(nearestNeighbour(p.position, i), 0.01, 1e-6);
    EXPECT_EQ(p.surface[i], 1);
    EXPECT_FLOAT_EQ(p.radius[i], 0.005f);
  }
  expectUnitOutwardNormals(p, c);
  // A rigid body sampled on its surface weighs what its whole volume does, shared equally;
  // its described faces lie half a spacing outside the particles.
  const double volume = 0.21 * 0.11 * 0.05;
  EXPECT_NEAR(world.info(0).mass, 1000.0 * volume, 1e-6);
  EXPECT_FLOAT_EQ(p.mass[0], float(1000.0 * volume / double(p.size())));
}

TEST(ShapeSampling, SolidBoxFillsTheLatticeAndFlagsItsOuterLayer) {
  ObjectDesc d = box({0, 0, 0}, {0.03, 0.03, 0.03}, 0.01);
  d.shape.solid = true;
  const ObjectWorld world({d}, settings());
  const ParticleState& p = world.particles();
  ASSERT_EQ(p.size(), 7u * 7u * 7u);
  std::size_t surface = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 a{std::abs(p.position[i].x), std::abs(p.position[i].y), std::abs(p.position[i].z)};
    const bool outer = std::max({a.x, a.y, a.z}) > 0.0299f;
    EXPECT_EQ(p.surface[i], outer ? 1 : 0);
    surface += p.surface[i];
  }
  EXPECT_EQ(surface, 7u * 7u * 7u - 5u * 5u * 5u);
}

TEST(ShapeSampling, SphereIsAnEvenFibonacciShell) {
  const ObjectWorld world({sphere({0, 0.3, 0}, 0.05, 0.01)}, settings());
  const ParticleState& p = world.particles();
  ASSERT_EQ(p.size(), std::size_t(std::lround(4 * kPi * 0.05 * 0.05 / 1e-4)));  // 314
  double sum = 0, smallest = 1;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(test::distance(p.position[i], {0, 0.3f, 0}), 0.05, 1e-6);
    const double nn = nearestNeighbour(p.position, i);
    sum += nn;
    smallest = std::min(smallest, nn);
  }
  // An even cover at one particle per s² has neighbours about s apart, none much closer.
  EXPECT_NEAR(sum / p.size(), 0.01, 0.001);
  EXPECT_GT(smallest, 0.75 * 0.01);
  expectUnitOutwardNormals(p, {0, 0.3f, 0});
}

TEST(ShapeSampling, SolidSphereIsConcentricShellsDownToACentre) {
  ObjectDesc d = sphere({0, 0, 0}, 0.05, 0.01);
  d.shape.solid = true;
  const ObjectWorld world({d}, settings());
  const ParticleState& p = world.particles();
  // Shells of radius 5, 4, 3, 2, 1 spacings (round(4π k²) points each) and the centre.
  ASSERT_EQ(p.size(), 314u + 201u + 113u + 50u + 13u + 1u);
  for (std::size_t i = 0; i < p.size(); ++i)
    EXPECT_EQ(p.surface[i], length(p.position[i]) > 0.0499f ? 1 : 0);
  EXPECT_FALSE(world.enclosesVolume(0));
}

TEST(ShapeSampling, CapsuleIsAtItsRadiusFromTheSegment) {
  ObjectDesc d;
  d.shape.kind = ShapeKind::Capsule;
  d.shape.center = {0.1, 0.2, 0.3};
  d.shape.radius = 0.0225;  // the particles lie half a spacing inside
  d.shape.length = 0.04;
  d.shape.axis = {0, 1, 0};
  d.spacing = 0.005;
  const ObjectWorld world({d}, settings());
  const ParticleState& p = world.particles();
  ASSERT_GT(p.size(), 100u);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 x = p.position[i];
    const float t = std::clamp(x.y - 0.2f, -0.02f, 0.02f);
    const Vec3 closest{0.1f, 0.2f + t, 0.3f};
    EXPECT_NEAR(test::distance(x, closest), 0.02, 1e-6);
    const Vec3 radial = (x - closest) / 0.02f;
    EXPECT_NEAR(test::distance(p.normal[i], radial), 0.0, 1e-5);
    const double nn = nearestNeighbour(p.position, i);
    EXPECT_GT(nn, 0.7 * 0.005);
    EXPECT_LT(nn, 1.2 * 0.005);
  }
  // Area 2π r L + 4π r² over s² per particle.
  const double area = 2 * kPi * 0.02 * 0.04 + 4 * kPi * 0.02 * 0.02;
  EXPECT_NEAR(double(p.size()), area / (0.005 * 0.005), 0.1 * area / (0.005 * 0.005));
}

TEST(ShapeSampling, CappedTubeHasRingsAndEndDiscs) {
  const ObjectWorld world({tube({0, 0, 0}, 0.02, 0.1, 0.005)}, settings());
  const ParticleState& p = world.particles();
  // 21 rings of round(2π·4) = 25; each disc has rings of 19, 13 and 6 and a centre.
  ASSERT_EQ(p.size(), 21u * 25u + 2u * (19u + 13u + 6u + 1u));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 x = p.position[i];
    const double radial = std::hypot(x.y, x.z);
    const bool wall = std::abs(radial - 0.02) < 1e-6;
    const bool cap = std::abs(std::abs(x.x) - 0.05) < 1e-6;
    EXPECT_TRUE(wall || cap) << "particle " << i << " off the tube";
    if (wall && !cap) {
      EXPECT_NEAR(p.normal[i].x, 0.0, 1e-6);
      EXPECT_NEAR(p.normal[i].y * x.y + p.normal[i].z * x.z, radial, 1e-6);
    }
    if (cap && !wall) {
      EXPECT_FLOAT_EQ(p.normal[i].x, x.x > 0 ? 1.0f : -1.0f);
    }
    const double nn = nearestNeighbour(p.position, i);
    EXPECT_GT(nn, 0.9 * 0.005);
    EXPECT_LT(nn, 1.05 * 0.005);
  }
  expectUnitOutwardNormals(p, {0, 0, 0});
  EXPECT_TRUE(world.enclosesVolume(0));
}

TEST(ShapeSampling, SecondLayerOfATubeIsOneSpacingInside) {
  ObjectDesc d = tube({0, 0, 0}, 0.02, 0.1, 0.005);
  d.shape.capped = false;
  d.shape.layers = 2;
  const ObjectWorld world({d}, settings());
  const ParticleState& p = world.particles();
  // Outer layer: 21 rings of 25; inner: 21 rings of round(2π·3) = 19.
  ASSERT_EQ(p.size(), 21u * 25u + 21u * 19u);
  std::size_t outer = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double radial = std::hypot(p.position[i].y, p.position[i].z);
    const bool isOuter = std::abs(radial - 0.02) < 1e-6;
    EXPECT_TRUE(isOuter || std::abs(radial - 0.015) < 1e-6);
    EXPECT_EQ(p.surface[i], isOuter ? 1 : 0);
    outer += isOuter;
  }
  EXPECT_EQ(outer, 21u * 25u);
  EXPECT_FALSE(world.enclosesVolume(0));
  EXPECT_FALSE(world.interiorContains(0, {0, 0, 0}, 0.0f));
}

TEST(ShapeSampling, CappedTubeInteriorEndsAtTheWallAndCapsLessTheMargin) {
  const ObjectWorld world({tube({0, 0, 0}, 0.02, 0.1, 0.005)}, settings());
  const float margin = 0.005f;
  EXPECT_TRUE(world.interiorContains(0, {0, 0, 0}, margin));
  EXPECT_TRUE(world.interiorContains(0, {0.0f, 0.0149f, 0.0f}, margin));
  EXPECT_FALSE(world.interiorContains(0, {0.0f, 0.0151f, 0.0f}, margin));
  EXPECT_TRUE(world.interiorContains(0, {0.0f, 0.0f, -0.0149f}, margin));
  EXPECT_TRUE(world.interiorContains(0, {0.0449f, 0.0f, 0.0f}, margin));
  EXPECT_FALSE(world.interiorContains(0, {0.0451f, 0.0f, 0.0f}, margin));
  EXPECT_FALSE(world.interiorContains(0, {-0.0451f, 0.0f, 0.0f}, margin));
  EXPECT_FALSE(world.interiorContains(0, {0.0f, 0.05f, 0.0f}, 0.0f));
}

TEST(ShapeSampling, BoxInteriorIsInsideItsInnermostLayer) {
  ObjectDesc hollow = box({0, 0, 0}, {0.05, 0.05, 0.05}, 0.01);
  ObjectDesc thick = box({1, 0, 0}, {0.05, 0.05, 0.05}, 0.01);
  thick.shape.layers = 2;
  ObjectDesc solid = box({2, 0, 0}, {0.05, 0.05, 0.05}, 0.01);
  solid.shape.solid = true;
  const ObjectWorld world({hollow, thick, solid}, settings());
  EXPECT_TRUE(world.enclosesVolume(0));
  EXPECT_TRUE(world.interiorContains(0, {0.0449f, -0.0449f, 0.0449f}, 0.005f));
  EXPECT_FALSE(world.interiorContains(0, {0.0451f, 0.0f, 0.0f}, 0.005f));
  EXPECT_FALSE(world.interiorContains(0, {0.0f, -0.0451f, 0.0f}, 0.005f));
  EXPECT_TRUE(world.interiorContains(1, {1.0349f, 0.0f, 0.0f}, 0.005f));
  EXPECT_FALSE(world.interiorContains(1, {1.0351f, 0.0f, 0.0f}, 0.005f));
  EXPECT_FALSE(world.enclosesVolume(2));
  EXPECT_FALSE(world.interiorContains(2, {2.0f, 0.0f, 0.0f}, 0.0f));
}

TEST(ShapeSampling, SphereInteriorIsTheBallLessTheMargin) {
  const ObjectWorld world({sphere({0, 0, 0}, 0.05, 0.01)}, settings());
  EXPECT_TRUE(world.interiorContains(0, {0.0449f, 0.0f, 0.0f}, 0.005f));
  EXPECT_FALSE(world.interiorContains(0, {0.0f, 0.0451f, 0.0f}, 0.005f));
}

TEST(ShapeSampling, ZeroSpacingTakesTheDefault) {
  ObjectDesc d = sphere({0, 0, 0}, 0.05, 0.0);
  const ObjectWorld world({d}, settings());  // default spacing 0.01
  EXPECT_EQ(world.particles().size(), 314u);
  EXPECT_FLOAT_EQ(world.particles().radius[0], 0.005f);
}

// A unit cube, outward winding, written next to a scene in a fresh folder.
std::string writeCubeScene() {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("sph_objects_mesh_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::ofstream obj(folder / "cube.obj");
  obj << "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
         "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
         "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";
  return folder.string();
}

TEST(ShapeSampling, MeshIsScaledPlacedAndSampledOnItsSurface) {
  ObjectDesc d;
  d.shape.kind = ShapeKind::Mesh;
  d.shape.meshFile = "cube.obj";  // relative to the scene's folder
  d.shape.scale = 0.1;
  d.shape.center = {1, 0, 0};
  d.spacing = 0.01;
  WorldSettings s = settings();
  s.sceneFolder = writeCubeScene();
  const ObjectWorld world({d}, s);
  const ParticleState& p = world.particles();
  ASSERT_GT(p.size(), 6u * 50u);
  const Vec3 c{1, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 x = p.position[i] - c;
    // Half a spacing inside its face, along the face's normal.
    EXPECT_NEAR(dot(x, p.normal[i]), 0.045, 1e-5);
    EXPECT_EQ(p.surface[i], 1);
  }
  expectUnitOutwardNormals(p, c);
  EXPECT_TRUE(world.enclosesVolume(0));
  EXPECT_TRUE(world.interiorContains(0, c, 0.005f));
  EXPECT_TRUE(world.interiorContains(0, c + Vec3{0.04f, 0.0f, 0.0f}, 0.005f));
  // Inside the mesh but within the margin of a particle (the test the mesh interior uses).
  std::size_t onFace = p.size();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.position[i].x > 1.0449f &&
        (onFace == p.size() || length(p.position[i] - c) < length(p.position[onFace] - c)))
      onFace = i;
  ASSERT_LT(onFace, p.size());
  EXPECT_FALSE(world.interiorContains(0, p.position[onFace] - Vec3{0.003f, 0.0f, 0.0f}, 0.005f));
  EXPECT_TRUE(world.interiorContains(0, p.position[onFace] - Vec3{0.006f, 0.0f, 0.0f}, 0.005f));
  EXPECT_FALSE(world.interiorContains(0, c + Vec3{0.06f, 0.0f, 0.0f}, 0.0f));

  d.shape.solid = true;
  const ObjectWorld solid({d}, s);
  EXPECT_FALSE(solid.enclosesVolume(0));
  const ParticleState& q = solid.particles();
  std::size_t surface = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    const Vec3 x = q.position[i] - c;
    const float depth = 0.05f - std::max({std::abs(x.x), std::abs(x.y), std::abs(x.z)});
    EXPECT_GE(depth, -1e-6f);
    if (q.surface[i]) {
      EXPECT_LE(depth, 0.01f + 1e-6f);
    }
    surface += q.surface[i];
  }
  EXPECT_GT(surface, 0u);
  EXPECT_LT(surface, q.size());
  std::filesystem::remove_all(s.sceneFolder);
}

}  // namespace
}  // namespace sph::objects
