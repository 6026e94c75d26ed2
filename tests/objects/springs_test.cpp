// Deformables (src/objects/springs.*): a pinned chain hangs with k Δl = weight below, springs
// break past their strain and mark the cut, cut boxes start broken, and normals follow.
#include <gtest/gtest.h>

#include <cmath>

#include "hanging_chains.hpp"
#include "object_scenes.hpp"

namespace sph::objects {
namespace {

using test::settings;

constexpr double kSpacing = test::kChainSpacing;
constexpr double kStiffness = test::kChainStiffness;
using test::chain;
using test::hangingChains;
using test::kChainLength;
const Vec3 kGravity = test::kChainGravity;

TEST(Springs, PinnedChainHangsWithStretchEqualToTheWeightBelow) {
  ObjectWorld world({hangingChains()}, settings(kGravity));
  ASSERT_EQ(world.particles().size(), 4u * kChainLength);
  EXPECT_EQ(world.info(0).springs, 4u * (kChainLength - 1));
  const std::vector<Vec3> start = world.particles().position;
  for (int s = 0; s < 3000; ++s) world.step(1e-3, {});
  const ParticleState& p = world.particles();
  const double m = p.mass[0];
  for (float xs : {-1.0f, 1.0f})
    for (float zs : {-1.0f, 1.0f}) {
      const std::vector<std::size_t> ids = chain(p, xs, zs);
      ASSERT_EQ(ids.size(), std::size_t(kChainLength));
      EXPECT_EQ(p.pinned[ids[0]], 1);
      EXPECT_EQ(p.position[ids[0]].y, start[ids[0]].y);  // pinned: not moved at all
      for (int j = 1; j < kChainLength; ++j) {
        // Spring j holds the particles j .. 9 below it: k Δl = (10 − j) m g.
        const double stretch = p.position[ids[j - 1]].y - p.position[ids[j]].y - kSpacing;
        const double expected = (kChainLength - j) * m * 9.81 / kStiffness;
        EXPECT_NEAR(stretch, expected, 0.01 * expected) << "spring " << j;
        EXPECT_NEAR(p.velocity[ids[j]].y, 0.0, 1e-4);
      }
    }
  EXPECT_EQ(world.info(0).brokenSprings, 0u);
}

TEST(Springs, SpringBreaksPastItsStrainAndMarksTheCut) {
  test::expectLinksBreakPastTheirStrainAndMarkTheCut(DeformableModel::Springs);
}

TEST(Springs, CutBoxStartsSpringsBrokenAndTheLowerPartFalls) {
  test::expectCutBoxStartsLinksBrokenAndTheLowerPartFalls(DeformableModel::Springs);
}

TEST(Springs, DefaultStiffnessStrainsOneSpringOnePercentUnderTheWholeWeight) {
  // Four independent pairs of particles, each joined by one spring and pinned at the top. The
  // default stiffness strains one spring 1 % under the whole object's weight (8 particles), so
  // a spring holding one particle settles at 1 %/8.
  ObjectDesc d = test::box({0, 0, 0}, {0.7 * kSpacing, 0.5 * kSpacing, 0.7 * kSpacing}, kSpacing,
                           ObjectMotion::Deformable);
  d.deformable.springReach = 1.2;
  d.deformable.pinned.push_back({{-1, 0.004, -1}, {1, 1, 1}});
  ObjectWorld world({d}, settings(kGravity));
  ASSERT_EQ(world.particles().size(), 8u);
  for (int s = 0; s < 2000; ++s) world.step(1e-3, {});
  const ParticleState& p = world.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.pinned[i]) continue;
    const double strain = (0.005 - p.position[i].y) / kSpacing - 1.0;
    EXPECT_NEAR(strain, 0.01 / 8.0, 0.01 * 0.01 / 8.0);
  }
}

TEST(Springs, NormalsTurnWithTheSurface) {
  // A solid plate three particles thick, clamped at x < −0.045, bends under its own weight.
  ObjectDesc d = test::box({0, 0, 0}, {0.05, 0.005, 0.02}, 0.005, ObjectMotion::Deformable);
  d.shape.solid = true;
  d.deformable.stiffness = 1000.0;
  d.deformable.pinned.push_back({{-1, -1, -1}, {-0.0449, 1, 1}});
  ObjectWorld world({d}, settings(kGravity));
  const ParticleState& p = world.particles();
  // The top face along z = 0, by x.
  std::vector<std::size_t> top;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.position[i].y > 0.0049f && std::abs(p.position[i].z) < 1e-6f) top.push_back(i);
  std::sort(top.begin(), top.end(),
            [&](std::size_t a, std::size_t b) { return p.position[a].x < p.position[b].x; });
  ASSERT_EQ(top.size(), 21u);
  for (std::size_t k = 1; k + 1 < top.size(); ++k)  // the ends are edges, normals at 45°
    EXPECT_NEAR(test::distance(p.normal[top[k]], {0, 1, 0}), 0.0, 1e-5);

  for (int s = 0; s < 500; ++s) world.step(1e-3, {});
  double largestTilt = 0.0;
  for (std::size_t k = 1; k + 1 < top.size(); ++k) {
    const std::size_t i = top[k];
    if (p.pinned[i]) continue;  // keeps its rest normal
    const Vec3 chord = p.position[top[k + 1]] - p.position[top[k - 1]];
    const Vec3 tangent = chord / length(chord);
    EXPECT_NEAR(length(p.normal[i]), 1.0, 1e-5);
    // Perpendicular to the bent surface (to within a small fraction of the tilt itself).
    EXPECT_LT(std::abs(dot(p.normal[i], tangent)), 0.02) << "top particle " << k;
    EXPECT_GT(p.normal[i].y, 0.0f);
    largestTilt = std::max(largestTilt, double(std::asin(-tangent.y)));
  }
  EXPECT_GT(largestTilt, 0.1);  // the plate did bend
}

}  // namespace
}  // namespace sph::objects
