// A closed XPBD vessel filled with liquid keeps its volume (src/objects/volume_constraint.*): a
// clamp squeezing it makes it bulge elsewhere instead of shrinking, measured by the areas of its
// rings, which the constraint does not read; the constraint reads a stretched shape's volume;
// a torn vessel lets its volume go; runs repeat bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "object_scenes.hpp"
#include "objects/volume_constraint.hpp"
#include "sph/core/constants.hpp"

namespace sph::objects {
namespace {

constexpr double kRadius = 0.01, kLength = 0.08, kSpacing = 0.0025;

// A capped vessel pinned at both ends, a clamp closing 8 mm on its middle from above in 0.1 s.
std::vector<ObjectDesc> clampedVessel(bool cut = false) {
  ObjectDesc vessel = test::tube({0, 0, 0}, kRadius, kLength, kSpacing);
  vessel.shape.capped = true;
  vessel.deformable.model = DeformableModel::Xpbd;
  vessel.deformable.stiffness = 100.0;
  vessel.deformable.bendingStiffness = 20.0;
  vessel.deformable.pinned = {{{-1, -1, -1}, {-0.035, 1, 1}}, {{0.035, -1, -1}, {1, 1, 1}}};
  if (cut) vessel.deformable.cuts = {{{0.015, -0.02, -0.0004}, {0.025, 0.02, 0.0004}}};
  ObjectDesc clamp =
      test::box({0, 0.0125 + 0.00125, 0}, {0.01, 0.00125, 0.015}, 0.0025, ObjectMotion::Kinematic);
  clamp.name = "clamp";
  clamp.keyframes = {{0.1, {0, -0.008, 0}, {0, 0, 0}}};
  return {vessel, clamp};
}

WorldSettings vesselSettings(bool liquidFilled) {
  WorldSettings s = test::settings();  // no gravity: nothing but the clamp moves the vessel
  s.contact = {50.0f, 0.005f, 0.0f};
  if (liquidFilled) s.liquidFilled = {0};
  return s;
}

// The vessel's rings (its caps' discs left out): each one's particles in the order of their
// angle at rest, as a polygon across the axis (x); its area and mean x now, and x at rest.
struct Section {
  double x, restX, area;
};

std::vector<Section> rings(const ObjectWorld& world, const std::vector<Vec3>& rest) {
  const ParticleState& p = world.particles();
  const ObjectInfo vessel = world.info(0);
  std::map<long, std::vector<std::pair<double, std::size_t>>> byRestX;  // in µm
  for (std::size_t i = vessel.firstParticle; i < vessel.firstParticle + vessel.particleCount; ++i) {
    const double r = std::hypot(double(rest[i].y), double(rest[i].z));
    if (std::abs(r - kRadius) > 0.1 * kSpacing) continue;  // a cap's disc
    const double angle = std::atan2(double(rest[i].z), double(rest[i].y));
    byRestX[std::lround(1e6 * rest[i].x)].push_back({angle, i});
  }
  std::vector<Section> sections;
  for (auto& [key, ring] : byRestX) {
    std::sort(ring.begin(), ring.end());
    double area = 0.0, x = 0.0;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec3 a = p.position[ring[k].second], b = p.position[ring[(k + 1) % ring.size()].second];
      area += 0.5 * (double(a.y) * b.z - double(b.y) * a.z);
      x += a.x;
    }
    sections.push_back({x / double(ring.size()), 1e-6 * double(key), std::abs(area)});
  }
  return sections;
}

// The volume inside the wall between the end rings: the rings' areas by the trapezoid rule.
double ringVolume(const std::vector<Section>& s) {
  double volume = 0.0;
  for (std::size_t k = 1; k < s.size(); ++k)
    volume += 0.5 * (s[k].area + s[k - 1].area) * (s[k].x - s[k - 1].x);
  return volume;
}

// The mean area of the rings beyond the clamp's reach (|x| > 2 cm at rest).
double areaBeyondTheClamp(const std::vector<Section>& s) {
  double sum = 0.0;
  int count = 0;
  for (const Section& section : s)
    if (std::abs(section.restX) > 0.02) {
      sum += section.area;
      ++count;
    }
  return sum / count;
}

struct Squeezed {
  double volumeRatio;  // after / before, by the rings
  double bulge;        // the rings' area beyond the clamp, after / before
  double topMiddle;    // m: the highest particle under the clamp
};

Squeezed squeeze(bool liquidFilled, bool cut = false) {
  ObjectWorld world(clampedVessel(cut), vesselSettings(liquidFilled));
  const std::vector<Vec3> rest = world.particles().position;
  const std::vector<Section> before = rings(world, rest);
  for (int step = 0; step < 200; ++step) world.step(1e-3, {});
  const std::vector<Section> after = rings(world, rest);
  Squeezed out{ringVolume(after) / ringVolume(before),
               areaBeyondTheClamp(after) / areaBeyondTheClamp(before), -1.0};
  const ParticleState& p = world.particles();
  const ObjectInfo vessel = world.info(0);
  for (std::size_t i = vessel.firstParticle; i < vessel.firstParticle + vessel.particleCount; ++i)
    if (std::abs(p.position[i].x) < 0.003f)
      out.topMiddle = std::max(out.topMiddle, double(p.position[i].y));
  return out;
}

TEST(VolumeConstraint, ASqueezedLiquidFilledVesselBulgesInsteadOfShrinking) {
  const Squeezed empty = squeeze(false), filled = squeeze(true);
  std::printf(
      "  after the squeeze, of the start: volume %.1f %% empty, %.1f %% filled; rings' "
      "area beyond the clamp %.1f %% and %.1f %%\n",
      100.0 * empty.volumeRatio, 100.0 * filled.volumeRatio, 100.0 * empty.bulge,
      100.0 * filled.bulge);
  // The clamp closed on both: its bottom stands at 4.5 mm, the vessel's top was at 1 cm.
  EXPECT_LT(empty.topMiddle, 0.0055);
  EXPECT_LT(filled.topMiddle, 0.0055);
  EXPECT_LT(empty.volumeRatio, 0.9) << "the clamp should squeeze an empty vessel's volume";
  EXPECT_NEAR(filled.volumeRatio, 1.0, 0.02) << "a liquid-filled vessel keeps its volume";
  EXPECT_GT(filled.bulge, 1.02) << "and bulges beyond the clamp";
  EXPECT_LT(empty.bulge, 1.0);
}

TEST(VolumeConstraint, ATornVesselLetsItsVolumeGo) {
  const Squeezed empty = squeeze(false, true), filled = squeeze(true, true);
  EXPECT_LT(filled.volumeRatio, 0.9);
  EXPECT_NEAR(filled.volumeRatio, empty.volumeRatio, 1e-12) << "the constraint should lapse";
}

TEST(VolumeConstraint, ReadsTheVolumeOfAStretchedShape) {
  ObjectWorld world(clampedVessel(), vesselSettings(true));
  const ParticleState& p = world.particles();
  const ObjectInfo vessel = world.info(0);
  std::vector<DVec3> position;
  for (const Vec3& x : p.position) position.push_back(toD(x));
  std::vector<std::uint32_t> surface;
  for (std::size_t i = vessel.firstParticle; i < vessel.firstParticle + vessel.particleCount; ++i)
    surface.push_back(std::uint32_t(i));
  // Each particle's neighbours: the vessel's particles within 1.5 spacings.
  std::vector<std::uint32_t> start{0}, neighbours;
  for (std::uint32_t i : surface) {
    for (std::uint32_t j : surface)
      if (j != i && norm(position[j] - position[i]) < 1.5 * kSpacing) neighbours.push_back(j);
    start.push_back(std::uint32_t(neighbours.size()));
  }
  const double v0 = kPi * kRadius * kRadius * kLength;
  const VolumeConstraint c = makeVolumeConstraint(0, 0, surface, v0, position, p.normal,
                                                  vessel.firstParticle, start, neighbours);
  EXPECT_NEAR(enclosedVolume(c, position, p.normal), v0, 1e-9 * v0);  // by construction
  // What makes it so is each particle's share of the shape's surface, the side and the caps:
  // measured 0.953 of it, the normals at the caps' rims leaning between side and cap.
  const double area = 2.0 * kPi * kRadius * (kLength + kRadius);
  std::printf("  the particles' rest areas sum to %.4f of the tube's surface\n",
              c.restArea * double(surface.size()) / area);
  EXPECT_NEAR(c.restArea * double(surface.size()) / area, 1.0, 0.1);
  // Stretched by 5 % every way about its centre, its normals unchanged: 1.05³ the volume.
  std::vector<DVec3> stretched = position;
  for (std::uint32_t i : surface) stretched[i] = position[i] * 1.05;
  EXPECT_NEAR(enclosedVolume(c, stretched, p.normal) / v0, 1.05 * 1.05 * 1.05, 1e-6);
  // Moved, the same.
  std::vector<DVec3> moved = position;
  for (std::uint32_t i : surface) moved[i] = position[i] + DVec3{0.3, -0.1, 0.2};
  EXPECT_NEAR(enclosedVolume(c, moved, p.normal) / v0, 1.0, 1e-6);
}

TEST(VolumeConstraint, RunsRepeatBitForBit) {
  ObjectWorld a(clampedVessel(), vesselSettings(true)), b(clampedVessel(), vesselSettings(true));
  for (int step = 0; step < 60; ++step) {
    a.step(1e-3, {});
    b.step(1e-3, {});
  }
  test::expectSameBytes(a.particles(), b.particles());
}

}  // namespace
}  // namespace sph::objects
