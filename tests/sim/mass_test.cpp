// Mass: particle count and total mass are constant while fluid stays in the domain; what
// leaves it is removed (or clamped back, by scene option) and counted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

TEST(Mass, ConstantInATank) {
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.fluid.blocks[0].box.min[1] = 0.05;  // a block dropped into the tank
  scene.fluid.blocks[0].box.max[1] = 0.15;
  Simulation sim(scene);
  const auto n0 = sim.fluidCount();
  sim.advanceTo(0.3);
  EXPECT_GT(sim.stepCount(), 100u);
  EXPECT_EQ(sim.fluidCount(), n0);
  EXPECT_EQ(sim.removedCount(), 0u);
  // Every particle (each of the same mass) is still there once: the ids are those it started
  // with, none lost, none doubled.
  const ParticleFrame f = sim.frame(false);
  std::vector<std::uint32_t> ids;
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f.kind[i] == static_cast<std::uint8_t>(ParticleKind::Fluid)) ids.push_back(f.id[i]);
  std::sort(ids.begin(), ids.end());
  ASSERT_EQ(ids.size(), n0);
  for (std::size_t k = 0; k < ids.size(); ++k) ASSERT_EQ(ids[k], k) << "lost or doubled";
}

// A block falls through the bottom of an open domain.
Scene fallingThroughTheFloor(OutsidePolicy policy) {
  Scene s;
  s.sourcePath = "falling (test)";
  s.fluid.spacing = 0.01;
  s.domain.box = {{0, 0, 0}, {0.2, 0.2, 0.2}};
  s.domain.outside = policy;
  s.fluid.blocks.push_back({{{0.05, 0.02, 0.05}, {0.15, 0.1, 0.15}}, {0, -1.0, 0}, false, ""});
  return s;
}

TEST(Mass, ParticlesLeavingTheDomainAreRemovedAndCounted) {
  Simulation sim(fallingThroughTheFloor(OutsidePolicy::Remove));
  const auto n0 = sim.fluidCount();
  sim.advanceTo(0.05);  // the lower half of the block has fallen out
  EXPECT_GT(sim.removedCount(), 0u);
  EXPECT_LT(sim.removedCount(), n0);
  EXPECT_EQ(sim.fluidCount() + sim.removedCount(), n0);
  EXPECT_EQ(sim.stats().removedCount, sim.removedCount());
  // The survivors keep their ids: unique, and all from the initial set.
  const ParticleFrame f = sim.frame(false);
  const std::set<std::uint32_t> ids(f.id.begin(), f.id.end());
  EXPECT_EQ(ids.size(), f.size());
  EXPECT_LT(*ids.rbegin(), n0);
  EXPECT_TRUE(std::is_sorted(f.id.begin(), f.id.end()));
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_GE(f.position[3 * i + 1], 0.0f);
}

TEST(Mass, ClampKeepsEveryParticleInside) {
  Simulation sim(fallingThroughTheFloor(OutsidePolicy::Clamp));
  const auto n0 = sim.fluidCount();
  sim.advanceTo(0.1);
  EXPECT_EQ(sim.removedCount(), 0u);
  EXPECT_EQ(sim.fluidCount(), n0);
  EXPECT_GT(sim.clampedCount(), 0u) << "the clamps are counted";
  const ParticleFrame f = sim.frame(false);
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_GE(f.position[3 * i + 1], 0.0f);
    EXPECT_LE(f.position[3 * i + 1], 0.2f);
  }
}

}  // namespace
}  // namespace sph
