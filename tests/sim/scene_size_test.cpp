// The size of a scene known before it is sampled (src/sim/scene_size.cpp): a scene is refused on
// this estimate, so it must never be below what a Simulation then makes, or a scene too large
// for the machine would pass and fail later in an allocation. A block's lattice is counted before
// walls and objects clip it, a wall's and an object's surface with an allowance for the
// lattice's rounding.
#include "sim/scene_size.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

// Water in a tank, open or closed; with an obstacle of each kind but mesh standing in it; under a
// floating box.
std::vector<Scene> smallScenes() {
  std::vector<Scene> scenes;
  scenes.push_back(testing::restingTank(0.02, 0.1, 0.1));
  // A closed tank one layer thick: its shell is nearly all surface, the tightest case.
  Scene shell = testing::restingTank(0.02, 0.1, 0.1);
  shell.walls[0].closed = true;
  shell.walls[0].layers = 1;
  scenes.push_back(shell);

  Scene obstacles = testing::restingTank(0.02, 0.16, 0.1);
  WallDesc box;
  box.kind = WallKind::Box;
  box.box = {{0.02, 0.0, 0.02}, {0.06, 0.04, 0.06}};
  obstacles.walls.push_back(box);
  WallDesc ball;
  ball.kind = WallKind::Sphere;
  ball.center = {0.12, 0.06, 0.12};
  ball.radius = 0.025;
  obstacles.walls.push_back(ball);
  WallDesc post;
  post.kind = WallKind::Cylinder;
  post.center = {0.04, 0.05, 0.12};
  post.axis = {0, 1, 0};
  post.radius = 0.025;
  post.length = 0.1;
  obstacles.walls.push_back(post);
  WallDesc ramp;
  ramp.kind = WallKind::Plane;
  ramp.corner = {0.0, 0.0, 0.0};
  ramp.edge1 = {0.0, 0.0, 0.16};
  ramp.edge2 = {0.06, 0.03, 0.0};
  obstacles.walls.push_back(ramp);
  scenes.push_back(obstacles);

  Scene floating = testing::restingTank(0.02, 0.12, 0.08);
  floating.domain.box.max[1] = 0.4;
  ObjectDesc raft;
  raft.name = "raft";
  raft.shape.kind = ShapeKind::Box;
  raft.shape.center = {0.06, 0.12, 0.06};
  raft.shape.halfExtents = {0.04, 0.02, 0.04};
  raft.density = 500.0;
  floating.objects.push_back(raft);
  scenes.push_back(floating);
  return scenes;
}

TEST(SceneSize, NeverCountsFewerParticlesThanASimulationMakes) {
  for (const Scene& scene : smallScenes()) {
    const sim::SceneSize size = sim::estimateSize(scene);
    Simulation sim(scene);
    const Calibration& made = sim.calibration();
    SCOPED_TRACE(std::to_string(scene.walls.size()) + " walls, " +
                 std::to_string(scene.objects.size()) + " objects");
    ASSERT_GT(made.fluidParticles, 0u);
    ASSERT_GT(made.boundaryParticles, 0u);
    EXPECT_GE(size.fluidParticles, double(made.fluidParticles));
    EXPECT_GE(size.wallParticles, double(made.boundaryParticles));
    EXPECT_GE(size.objectParticles, double(made.objectParticles));
    if (!scene.objects.empty()) {
      EXPECT_GT(made.objectParticles, 0u);
    }
  }
}

// Nothing clips a block that stands clear of the walls: its lattice is counted exactly.
TEST(SceneSize, CountsAnUnclippedBlockExactly) {
  const Scene scene = testing::restingTank(0.02, 0.1, 0.1);
  Simulation sim(scene);
  EXPECT_EQ(sim::estimateSize(scene).fluidParticles, double(sim.calibration().fluidParticles));
  EXPECT_EQ(sim.calibration().fluidParticles, 5u * 5u * 5u);
}

TEST(SceneSize, TheMemoryGrowsWithEachKindOfParticle) {
  const Scene base = testing::restingTank(0.02, 0.1, 0.1);
  const sim::SceneSize size = sim::estimateSize(base);
  EXPECT_GT(size.bytes, 0.0);

  Scene finer = testing::restingTank(0.01, 0.1, 0.1);
  const sim::SceneSize fine = sim::estimateSize(finer);
  EXPECT_GT(fine.fluidParticles, size.fluidParticles);
  EXPECT_GT(fine.wallParticles, size.wallParticles);
  EXPECT_GT(fine.bytes, size.bytes);

  Scene moreFluid = base;
  moreFluid.fluid.blocks.push_back({{{0.0, 0.1, 0.0}, {0.1, 0.12, 0.1}}, {0, 0, 0}, false, ""});
  const sim::SceneSize fluid = sim::estimateSize(moreFluid);
  EXPECT_GT(fluid.fluidParticles, size.fluidParticles);
  EXPECT_EQ(fluid.wallParticles, size.wallParticles);
  EXPECT_GT(fluid.bytes, size.bytes);

  Scene moreWall = base;
  WallDesc box;
  box.kind = WallKind::Box;
  box.box = {{0.02, 0.0, 0.02}, {0.06, 0.04, 0.06}};
  moreWall.walls.push_back(box);
  const sim::SceneSize wall = sim::estimateSize(moreWall);
  EXPECT_EQ(wall.fluidParticles, size.fluidParticles);
  EXPECT_GT(wall.wallParticles, size.wallParticles);
  EXPECT_GT(wall.bytes, size.bytes);

  Scene withObject = base;
  ObjectDesc ball;
  ball.shape.kind = ShapeKind::Sphere;
  ball.shape.radius = 0.05;
  withObject.objects.push_back(ball);
  const sim::SceneSize object = sim::estimateSize(withObject);
  EXPECT_GT(object.objectParticles, 0.0);
  EXPECT_GT(object.bytes, size.bytes);
  // Solid, it fills its volume: more particles than its surface alone.
  withObject.objects[0].shape.solid = true;
  EXPECT_GT(sim::estimateSize(withObject).objectParticles, object.objectParticles);
  EXPECT_GT(sim::estimateSize(withObject).bytes, object.bytes);
}

}  // namespace
}  // namespace sph
