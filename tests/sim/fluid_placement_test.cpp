// Where the fluid starts among objects: a block poured over a hollow box leaves out the box's
// inside and the reach of its particles; a block declared `inside` a vessel fills only it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sph/simulation.hpp"

namespace sph {
namespace {

constexpr double kSpacing = 0.01;

Scene blockOverBox() {
  Scene s;
  s.name = "block_over_box";
  s.sourcePath = "block_over_box (test)";
  s.gravity = {0, 0, 0};
  s.calibration.maxExpectedSpeed = 1.0;
  s.fluid.spacing = kSpacing;
  s.domain.box = {{-1, -1, -1}, {1, 1, 1}};
  FluidBlock block;
  block.box = {{0, 0, 0}, {0.1, 0.1, 0.1}};
  s.fluid.blocks.push_back(block);
  ObjectDesc box;
  box.name = "box";
  box.shape.kind = ShapeKind::Box;
  box.shape.center = {0.05, 0.05, 0.05};
  box.shape.halfExtents = {0.025, 0.025, 0.025};
  box.density = 500;
  s.objects.push_back(box);
  return s;
}

struct Split {
  std::vector<Vec3d> fluid, object;
};

Split particlesOf(Simulation& sim) {
  const ParticleFrame f = sim.frame(false);
  Split out;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Vec3d p{f.position[3 * i], f.position[3 * i + 1], f.position[3 * i + 2]};
    if (f.kind[i] == static_cast<std::uint8_t>(ParticleKind::Fluid)) out.fluid.push_back(p);
    if (f.kind[i] == static_cast<std::uint8_t>(ParticleKind::Object)) out.object.push_back(p);
  }
  return out;
}

double distance(const Vec3d& a, const Vec3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(FluidPlacement, BlockLeavesOutAHollowBodyAndTheReachOfItsParticles) {
  const Scene scene = blockOverBox();
  Simulation sim(scene);
  const Split p = particlesOf(sim);
  ASSERT_FALSE(p.object.empty());
  // Influence sphere reach: the fluid's radius + influence ratio × the object's radius.
  const double reach = 0.5 * kSpacing + scene.interaction.influenceRatio * 0.5 * kSpacing;
  std::size_t insideBox = 0;
  for (const Vec3d& x : p.fluid) {
    bool inside = true;
    for (int a = 0; a < 3; ++a) inside = inside && std::abs(x[a] - 0.05) < 0.025;
    insideBox += inside ? 1 : 0;
    for (const Vec3d& o : p.object) ASSERT_GE(distance(x, o), reach);
  }
  EXPECT_EQ(insideBox, 0u);
  // Something was left: the lattice points beyond the reach of the box.
  EXPECT_GT(p.fluid.size(), 500u);
  EXPECT_LT(p.fluid.size(), 1000u - 125u);
}

TEST(FluidPlacement, BlockInsideAVesselFillsOnlyIt) {
  Scene scene = blockOverBox();
  scene.fluid.blocks[0].inside = "box";
  Simulation sim(scene);
  const Split p = particlesOf(sim);
  ASSERT_GT(p.fluid.size(), 0u);
  for (const Vec3d& x : p.fluid)
    for (int a = 0; a < 3; ++a) EXPECT_LT(std::abs(x[a] - 0.05), 0.025);
}

}  // namespace
}  // namespace sph
