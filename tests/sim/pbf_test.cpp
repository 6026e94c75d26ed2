// The position-based solver (fluid.solver "pbf") as a whole: its substeps are time.frame_dt's,
// equal, and as many as keep a particle's move within 0.4 of its radius at the expected speed;
// its runs are the same bytes on any thread count; what it cannot do is refused by key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "backend/cpu_parallel.hpp"
#include "frame_checks.hpp"
#include "scene/scene_loader.hpp"
#include "scene_builders.hpp"
#include "sph/error.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

Scene shipped(const std::string& name, std::vector<std::string> overrides = {}) {
  return scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/" + name, overrides);
}

TEST(PositionSolver, SubstepsKeepEachMoveWithinAFractionOfTheRadius) {
  const Scene scene = shipped("dam_break.json", {"fluid.spacing=0.02", "fluid.solver=pbf"});
  Simulation sim(scene);
  const Calibration& c = sim.calibration();
  const double substep = scene.time.frameDt / c.substeps;
  EXPECT_LE(substep * c.maxExpectedSpeed, 0.4 * 0.5 * c.spacing);
  EXPECT_GT(substep * (1.0 + 1.0 / c.substeps) * c.maxExpectedSpeed, 0.4 * 0.5 * c.spacing)
      << "no more substeps than that asks";
  // Equal substeps, landing on the frames' times.
  sim.advanceTo(2.0 * scene.time.frameDt);
  EXPECT_EQ(sim.stepCount(), std::uint64_t(2 * c.substeps));
  EXPECT_NEAR(sim.lastDt(), substep, 1e-12);
  Scene set = scene;
  set.time.substeps = 3;
  EXPECT_EQ(Simulation(set).calibration().substeps, 3);
}

ParticleFrame splash(int threads) {
  backend::setThreadCount(threads);
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.fluid.solver = FluidSolver::Pbf;
  scene.fluid.blocks[0].box.min[1] = 0.05;
  scene.fluid.blocks[0].box.max[1] = 0.15;
  scene.fluid.blocks[0].velocity = {0.3, 0, -0.2};
  Simulation sim(scene);
  for (int i = 0; i < 30; ++i) sim.step();
  backend::setThreadCount(0);
  return sim.frame();
}

TEST(PositionSolver, OneAndTwoThreadsGiveTheSameBytes) {
  const ParticleFrame one = splash(1), two = splash(2);
  testing::expectIdenticalFrames(one, two);
  double moved = 0.0;
  for (float v : one.velocity) moved += std::abs(v);
  EXPECT_GT(moved, 0.0);
}

// The artery at half its blood's resolution: the vessel and clamps as boundary particles, the
// object engine stepped every substep.
ParticleFrame squeezeCoarse(int threads) {
  backend::setThreadCount(threads);
  Scene scene = shipped("artery_squeeze.json", {"fluid.spacing=0.002", "fluid.solver=pbf",
                                                "interaction.coupling=boundary"});
  Simulation sim(scene);
  sim.advanceTo(0.1);
  backend::setThreadCount(0);
  return sim.frame();
}

TEST(PositionSolver, WithObjectsOneAndTwoThreadsGiveTheSameBytes) {
  const ParticleFrame one = squeezeCoarse(1), two = squeezeCoarse(2);
  testing::expectIdenticalFrames(one, two);
}

// The loader's message for a shipped scene with `overrides`, or a scene built in code.
std::string refusal(const std::string& name, std::vector<std::string> overrides) {
  try {
    shipped(name, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
std::string refusal(const Scene& scene) {
  try {
    Simulation sim(scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PositionSolver, RefusesContactCouplingAndWallForceProbesByKey) {
  const std::string objects = refusal("floating_bodies.json", {"fluid.solver=pbf"});
  EXPECT_NE(objects.find("interaction.coupling: expected \"boundary\" with objects and "
                         "fluid.solver \"pbf\""),
            std::string::npos)
      << objects;
  EXPECT_EQ(refusal("floating_bodies.json", {"fluid.solver=pbf", "interaction.coupling=boundary"}),
            "");
  Scene probe = testing::restingTank(0.02, 0.1, 0.1);
  probe.fluid.solver = FluidSolver::Pbf;
  probe.walls[0].name = "tank";
  ProbeDesc p;
  p.name = "push";
  p.kind = ProbeKind::Force;
  p.wall = "tank";
  probe.probes.push_back(p);
  const std::string wall = refusal(probe);
  EXPECT_NE(wall.find("probes[0].wall: expected no force probe on a wall with fluid.solver"),
            std::string::npos)
      << wall;
  Scene continuity = testing::restingTank(0.02, 0.1, 0.1);
  continuity.fluid.solver = FluidSolver::Pbf;
  continuity.fluid.density = DensityModel::Continuity;
  EXPECT_NE(refusal(continuity)
                .find("fluid.density: expected \"summation\" with fluid.solver "
                      "\"pbf\""),
            std::string::npos);
}

}  // namespace
}  // namespace sph
