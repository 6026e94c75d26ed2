// The free-surface flags (Meteer 2011, eqs. 11-12), measured when a frame is taken: in a resting
// tank the top layer is surface, the water below it and against the walls is not, and the
// statistics count the flags the frame carries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

#include "backends.hpp"
#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

class SurfaceFlags : public ::testing::TestWithParam<Backend> {};

TEST_P(SurfaceFlags, TopLayerOfARestingTankAndNothingBelow) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  const double d = 0.01, width = 0.1, height = 0.1;
  Scene scene = testing::restingTank(d, width, height);
  scene.fluid.blocks[0].hydrostatic = true;
  Simulation sim(scene, testing::on(GetParam()));
  sim.advanceTo(0.3);
  const ParticleFrame f = sim.frame(false);

  float top = -1e9f;
  for (std::size_t i = 0; i < f.size(); ++i) top = std::max(top, f.position[3 * i + 1]);
  std::size_t topLayer = 0, topFlagged = 0, deep = 0, deepFlagged = 0, flagged = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f.kind[i] != std::uint8_t(ParticleKind::Fluid)) continue;
    const float y = f.position[3 * i + 1];
    flagged += f.surface[i];
    if (y > top - 0.5f * float(d)) {
      ++topLayer;
      topFlagged += f.surface[i];
    } else if (y < top - 2.5f * float(d)) {
      // Below the top's reach (h = 2d); the walls count as filled space.
      ++deep;
      deepFlagged += f.surface[i];
    }
  }
  ASSERT_GT(topLayer, 50u);
  ASSERT_GT(deep, 500u);
  EXPECT_GT(topFlagged, topLayer * 9 / 10) << topFlagged << " of " << topLayer << " on top";
  EXPECT_LT(deepFlagged, deep / 100) << deepFlagged << " of " << deep << " deep down";
  EXPECT_EQ(sim.stats().surfaceCount, flagged);
}

TEST_P(SurfaceFlags, NoneBeforeTheFirstStep) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Simulation sim(testing::restingTank(0.01, 0.1, 0.1), testing::on(GetParam()));
  const ParticleFrame f = sim.frame(false);
  for (std::uint8_t s : f.surface) ASSERT_EQ(s, 0);
  EXPECT_EQ(sim.stats().surfaceCount, 0u);
}

SPH_ON_EVERY_BACKEND(SurfaceFlags);

}  // namespace
}  // namespace sph
