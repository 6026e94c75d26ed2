// Four hanging chains, the deformables' test piece for both models (springs, XPBD), and the
// checks that must hold whichever model joins them.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "object_scenes.hpp"

namespace sph::objects::test {

constexpr double kChainSpacing = 0.01;
constexpr double kChainStiffness = 490.0;  // N/m: the top link of a chain strains ~1.8 %
constexpr int kChainLength = 10;
const Vec3 kChainGravity{0, -9.81f, 0};

// A thin box of 2 × 10 × 2 particles: columns 1.4 s apart, beyond the 1.2 s reach, so it is four
// independent vertical chains of 10 particles a spacing apart, pinned at the top. Each link
// joins two neighbours only: the chain's static stretch is exactly the weight below each link
// over k.
inline ObjectDesc hangingChains(DeformableModel model = DeformableModel::Springs,
                                double stiffness = kChainStiffness) {
  ObjectDesc d = box({0, 0, 0}, {0.7 * kChainSpacing, 4.5 * kChainSpacing, 0.7 * kChainSpacing},
                     kChainSpacing, ObjectMotion::Deformable);
  d.deformable.model = model;
  d.deformable.stiffness = stiffness;
  d.deformable.springReach = 1.2;
  d.deformable.pinned.push_back({{-1, 4.4 * kChainSpacing, -1}, {1, 1, 1}});
  return d;
}

// Particles of the chain at column (x, z) sign, from the top down.
inline std::vector<std::size_t> chain(const ParticleState& p, float xSign, float zSign) {
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.position[i].x * xSign > 0 && p.position[i].z * zSign > 0) ids.push_back(i);
  std::sort(ids.begin(), ids.end(),
            [&](std::size_t a, std::size_t b) { return p.position[a].y > p.position[b].y; });
  return ids;
}

// A link breaks past its strain and marks both its particles cut; below the limit nothing does.
inline void expectLinksBreakPastTheirStrainAndMarkTheCut(DeformableModel model) {
  ObjectDesc d = hangingChains(model);
  d.deformable.breakingStrain = 0.01;  // the top link would settle at 1.8 %
  ObjectWorld world({d}, settings(kChainGravity));
  const double startCentre = world.info(0).centreOfMass.y;
  for (int s = 0; s < 300; ++s) world.step(1e-3, {});
  const ParticleState& p = world.particles();
  EXPECT_GE(world.info(0).brokenSprings, 4u);  // at least the top link of each chain
  for (float xs : {-1.0f, 1.0f})
    for (float zs : {-1.0f, 1.0f}) {
      const std::vector<std::size_t> ids = chain(p, xs, zs);
      EXPECT_EQ(p.cut[ids[0]], 1);
      EXPECT_EQ(p.cut[ids[1]], 1);
    }
  // Torn off, the chains fall: ½ g t² = 0.44 m over 0.3 s for the free part.
  EXPECT_LT(world.info(0).centreOfMass.y, startCentre - 0.2);

  // With a limit above what the links reach, nothing breaks and nothing is cut.
  d.deformable.breakingStrain = 0.03;
  ObjectWorld holding({d}, settings(kChainGravity));
  for (int s = 0; s < 300; ++s) holding.step(1e-3, {});
  EXPECT_EQ(holding.info(0).brokenSprings, 0u);
  for (std::uint8_t c : holding.particles().cut) EXPECT_EQ(c, 0);
  EXPECT_GT(holding.info(0).centreOfMass.y, startCentre - 0.01);
}

// A cut box between two layers starts the links through it broken and the particles beside it
// cut; the part below falls freely, the part above still hangs.
inline void expectCutBoxStartsLinksBrokenAndTheLowerPartFalls(DeformableModel model) {
  ObjectDesc d = hangingChains(model);
  // A slit between the layers at y = 0.005 and y = 0.015: the links through it break.
  d.deformable.cuts.push_back({{-1, 0.0099, -1}, {1, 0.0101, 1}});
  ObjectWorld world({d}, settings(kChainGravity));
  EXPECT_EQ(world.info(0).brokenSprings, 4u);
  const ParticleState& p0 = world.particles();
  std::size_t cut = 0;
  for (std::size_t i = 0; i < p0.size(); ++i) {
    const bool besideTheSlit = std::abs(std::abs(p0.position[i].y - 0.01f) - 0.005f) < 0.001f;
    EXPECT_EQ(p0.cut[i], besideTheSlit ? 1 : 0) << "y = " << p0.position[i].y;
    cut += p0.cut[i];
  }
  EXPECT_EQ(cut, 8u);
  const std::vector<Vec3> start = p0.position;
  for (int s = 0; s < 200; ++s) world.step(1e-3, {});
  const ParticleState& p = world.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double drop = start[i].y - p.position[i].y;
    if (start[i].y < 0.01f) {
      EXPECT_NEAR(drop, 0.5 * 9.81 * 0.2 * 0.2, 0.01);  // free fall
    } else {
      EXPECT_LT(drop, 0.005);  // still hangs
    }
  }
}

}  // namespace sph::objects::test
