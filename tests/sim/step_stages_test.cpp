// Each solver's step is a list of named stages (src/sim/wcsph_step.cpp, dfsph_step.cpp,
// step_end.cpp) holding only the stages that have work in the scene: no stage runs to do
// nothing, and a stage's time lands in its own StepProfile bucket.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "scene/scene_loader.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

using Names = std::vector<std::string>;

Scene shipped(const std::string& name, std::vector<std::string> overrides = {}) {
  return scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/" + name, overrides);
}

Names stagesOf(const Scene& scene) {
  return Simulation(scene).stageNames();
}

TEST(StepStages, TheWeaklyCompressibleStepOfAFluidAlone) {
  const Scene damBreak = shipped("dam_break.json", {"fluid.spacing=0.02"});
  EXPECT_EQ(stagesOf(damBreak),
            (Names{"build grid", "density and pressure", "forces", "time step", "integrate"}));
  Simulation sim(damBreak);
  sim.step();
  const StepProfile& p = sim.lastProfile();
  EXPECT_EQ(p.divergenceSolve, 0.0);
  EXPECT_EQ(p.densitySolve, 0.0);
  EXPECT_EQ(p.interaction, 0.0);
  EXPECT_EQ(p.objects, 0.0);
  EXPECT_EQ(p.flow, 0.0);
  EXPECT_EQ(p.probes, 0.0);
  EXPECT_GT(p.forces, 0.0);
}

TEST(StepStages, ContinuityIntegratesTheDensityAfterTheSums) {
  EXPECT_EQ(stagesOf(shipped("dam_break.json", {"fluid.spacing=0.02", "fluid.density=continuity"})),
            (Names{"build grid", "density and pressure", "continuity density", "forces",
                   "time step", "integrate"}));
}

TEST(StepStages, TheIncompressibleStepSolvesTwice) {
  const Scene dfsph = shipped("dam_break.json", {"fluid.spacing=0.02", "fluid.solver=dfsph"});
  EXPECT_EQ(stagesOf(dfsph),
            (Names{"build grid", "density", "divergence solve", "non-pressure forces", "time step",
                   "density solve", "integrate"}));
  Scene noDensitySolve = dfsph;
  noDensitySolve.fluid.dfsph.densitySolve = false;
  EXPECT_EQ(stagesOf(noDensitySolve), (Names{"build grid", "density", "divergence solve",
                                             "non-pressure forces", "time step", "integrate"}));
}

// Macklin & Müller 2013: the positions predicted, the neighbours found there, the constraints
// projected; the forces found last are the next substep's.
TEST(StepStages, ThePositionBasedSubstepProjectsTheConstraints) {
  const Scene pbf = shipped("dam_break.json", {"fluid.spacing=0.02", "fluid.solver=pbf"});
  EXPECT_EQ(stagesOf(pbf),
            (Names{"time step", "predict positions", "build grid", "density", "density constraints",
                   "XSPH viscosity", "non-pressure forces", "advance clock"}));
  Scene noXsph = pbf;
  noXsph.fluid.pbf.xsph = 0.0;
  EXPECT_EQ(stagesOf(noXsph).size(), 7u);
  Simulation sim(pbf);
  sim.step();
  EXPECT_GT(sim.lastProfile().densitySolve, 0.0);
  EXPECT_EQ(sim.lastProfile().divergenceSolve, 0.0);
}

// Meteer 2011, §7: the objects' surface, collisions and contact forces, the forces on the
// objects, and the engine's own step.
TEST(StepStages, ObjectsAddTheInteraction) {
  EXPECT_EQ(stagesOf(shipped("artery_squeeze.json")),
            (Names{"build grid", "density and pressure", "forces", "contacts with objects",
                   "time step", "forces on objects", "integrate", "object step"}));
  EXPECT_EQ(stagesOf(shipped("artery_squeeze.json",
                             {"fluid.solver=dfsph", "interaction.coupling=boundary"})),
            (Names{"objects as boundary", "build grid", "density", "divergence solve",
                   "non-pressure forces", "containment", "time step", "density solve",
                   "forces on objects", "integrate", "object step"}));
}

// The pipe: an emitter, an outlet, point probes and a force probe on a wall.
TEST(StepStages, EmittersAndProbesAddTheirStages) {
  const Scene pipe = shipped("pipe_flow.json", {"fluid.spacing=0.01"});
  EXPECT_EQ(stagesOf(pipe),
            (Names{"build grid", "density and pressure", "forces", "time step", "forces on walls",
                   "drive inflow", "integrate", "emit", "probes"}));
  Scene withoutWallProbe = pipe;
  withoutWallProbe.probes.erase(
      std::remove_if(withoutWallProbe.probes.begin(), withoutWallProbe.probes.end(),
                     [](const ProbeDesc& p) { return !p.wall.empty(); }),
      withoutWallProbe.probes.end());
  EXPECT_EQ(stagesOf(withoutWallProbe),
            (Names{"build grid", "density and pressure", "forces", "time step", "drive inflow",
                   "integrate", "emit", "probes"}));
}

}  // namespace
}  // namespace sph
