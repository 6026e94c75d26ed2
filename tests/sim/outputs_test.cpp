// What a run measures beside the step (src/sim/outputs.cpp): the fluid's force on a wall costs
// a pass over the wall's particles, so only a force probe on a wall asks for it, and only the
// walls such a probe names are measured. The engine is a real CPU one, set up from a small scene
// as a Simulation sets up its own.
#include "sim/outputs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "sim/calibration.hpp"
#include "sim/sampling.hpp"
#include "sim/walls.hpp"

namespace sph {
namespace {

ProbeDesc probe(ProbeKind kind, const char* object, const char* wall) {
  ProbeDesc p;
  p.name = "p";
  p.kind = kind;
  p.object = object;
  p.wall = wall;
  return p;
}

TEST(Outputs, OnlyAForceProbeOnAWallAsksForWallForces) {
  Scene s;
  EXPECT_FALSE(sim::Outputs::probesWallForces(s));
  s.probes = {probe(ProbeKind::Point, "", ""), probe(ProbeKind::Level, "", "")};
  EXPECT_FALSE(sim::Outputs::probesWallForces(s));
  s.probes.push_back(probe(ProbeKind::Force, "ball", ""));  // on an object
  EXPECT_FALSE(sim::Outputs::probesWallForces(s));
  // A wall named on a probe of another kind is not a force probe.
  s.probes.push_back(probe(ProbeKind::Point, "", "tank"));
  s.probes.push_back(probe(ProbeKind::Level, "", "tank"));
  EXPECT_FALSE(sim::Outputs::probesWallForces(s));
  s.probes.push_back(probe(ProbeKind::Force, "", "tank"));
  EXPECT_TRUE(sim::Outputs::probesWallForces(s));
  Scene only;
  only.probes = {probe(ProbeKind::Force, "", "floor")};
  EXPECT_TRUE(sim::Outputs::probesWallForces(only));
}

// Water over a box standing on the floor of a tank, compressed as it rests, with a force probe
// on the box alone.
Scene boxInTank() {
  Scene s;
  s.name = "box_in_tank";
  s.sourcePath = "box_in_tank (test)";
  s.fluid.spacing = 0.01;
  s.calibration.speedOfSound = 2.0;  // slow: the resting compression is large
  s.domain.box = {{-0.05, -0.05, -0.05}, {0.11, 0.2, 0.11}};
  s.walls.push_back(WallDesc::tank({{0, 0, 0}, {0.06, 0.1, 0.06}}, 1, false));
  s.walls[0].name = "tank";
  WallDesc box;
  box.name = "box";
  box.kind = WallKind::Box;
  box.box = {{0.02, 0.0, 0.02}, {0.04, 0.02, 0.04}};
  box.layers = 1;
  s.walls.push_back(box);
  s.fluid.blocks.push_back({{{0, 0, 0}, {0.06, 0.06, 0.06}}, {0, 0, 0}, true, ""});
  ProbeDesc force;
  force.name = "on_box";
  force.kind = ProbeKind::Force;
  force.wall = "box";
  s.probes.push_back(force);
  return s;
}

bool inside(const Vec4& p, const AxisBox& b) {
  return p.x > b.min[0] && p.x < b.max[0] && p.y > b.min[1] && p.y < b.max[1] && p.z > b.min[2] &&
         p.z < b.max[2];
}

TEST(Outputs, WallParticlesMapToTheirWallsAndOnlyProbedWallsAreMeasured) {
  const Scene scene = boxInTank();
  const Calibration calibration = sim::calibrate(scene);
  const sim::Walls walls(scene);
  sim::EngineSetup setup = sim::engineSetup(scene, calibration, walls);
  const FluidBlock& block = scene.fluid.blocks[0];
  setup.positions = sim::sampleBlock(block.box, scene.fluid.spacing);
  walls.removeOverlap(setup.positions);
  sim::compressHydrostatically(setup.positions, block.box, scene.gravity, calibration.soundSpeed);
  setup.velocities.assign(setup.positions.size(), Vec3{0, 0, 0});
  setup.densities = sim::restingDensities(setup.positions, block.box, true, scene.gravity,
                                          calibration.soundSpeed, scene.fluid.restDensity);
  const std::unique_ptr<sim::FluidEngine> engine = sim::makeCpuEngine(setup);
  ASSERT_GT(engine->fluidCount(), 0u);
  ASSERT_LT(engine->fluidCount() + engine->wallCount(), 1000u);

  sim::Outputs outputs;
  outputs.mapWallParticles(*engine, walls, scene, setup.positions.size());
  ASSERT_EQ(outputs.fluidForceOnWall.size(), 2u);
  // The engine's wall order is its own: each particle's wall is told by where it lies, the
  // box's inside the obstacle, the tank's outside the fluid's room.
  const sim::HostWalls host = engine->downloadWalls();
  ASSERT_EQ(outputs.wallOfParticle.size(), host.position.size());
  std::size_t onBox = 0;
  for (std::size_t k = 0; k < host.position.size(); ++k) {
    const bool inBox = inside(host.position[k], scene.walls[1].box);
    EXPECT_EQ(outputs.wallOfParticle[k], inBox ? 1u : 0u) << "wall particle " << k;
    if (!inBox) {
      EXPECT_FALSE(inside(host.position[k], scene.walls[0].box));
    }
    onBox += inBox ? 1 : 0;
  }
  EXPECT_GT(onBox, 0u);

  engine->buildGrid();
  engine->computeDensityAndPressure();
  engine->computeForces();
  outputs.collectWallForces(*engine);
  const Vec3 tank = outputs.fluidForceOnWall[0], box = outputs.fluidForceOnWall[1];
  EXPECT_EQ(tank.x, 0.0f);  // not probed: not measured
  EXPECT_EQ(tank.y, 0.0f);
  EXPECT_EQ(tank.z, 0.0f);
  // The water over the box presses it down, and its sides push it alike from every side.
  EXPECT_LT(box.y, 0.0f);
  EXPECT_LT(std::abs(box.x), 0.1 * std::abs(box.y));
  EXPECT_LT(std::abs(box.z), 0.1 * std::abs(box.y));
}

}  // namespace
}  // namespace sph
