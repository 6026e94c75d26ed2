// Parameters changed while a simulation runs take effect from the next step; a kinematic object
// can be dragged by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sph/error.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

// A block of fluid falling freely: no walls, a domain far larger than the fall.
Scene fallingBlock() {
  Scene s;
  s.name = "falling_block";
  s.sourcePath = "falling_block (test)";
  s.fluid.spacing = 0.01;
  s.fluid.viscosity = 0.05;
  s.domain.box = {{-1, -1, -1}, {1, 1, 1}};
  FluidBlock block;
  block.box = {{0, 0, 0}, {0.05, 0.05, 0.05}};
  s.fluid.blocks.push_back(block);
  s.calibration.maxExpectedSpeed = 1.0;
  return s;
}

double meanVerticalVelocity(Simulation& sim) {
  const ParticleFrame f = sim.frame(false);
  double sum = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) sum += f.velocity[3 * i + 1];
  return sum / double(f.size());
}

TEST(LiveParameters, GravitySwitchedOffStopsTheFallAccelerating) {
  Simulation sim(fallingBlock());
  sim.advanceTo(0.05);
  const double falling = meanVerticalVelocity(sim);
  EXPECT_NEAR(falling, -9.81 * 0.05, 0.02);
  LiveParameters values = sim.liveParameters();
  EXPECT_DOUBLE_EQ(values.gravity[1], -9.81);
  values.gravity = {0, 0, 0};
  sim.setLiveParameters(values);
  sim.advanceTo(0.1);
  EXPECT_NEAR(meanVerticalVelocity(sim), falling, 0.01);
}

TEST(LiveParameters, StiffnessCarriesTheSpeedOfSoundAndTheTimeStep) {
  Simulation sim(fallingBlock());
  sim.advanceTo(0.01);
  sim.step();  // a whole step, not one shortened to end at 0.01 s
  const double c0 = sim.calibration().soundSpeed;
  const double dt = sim.lastDt();
  LiveParameters values = sim.liveParameters();
  values.stiffness *= 4.0;
  sim.setLiveParameters(values);
  EXPECT_NEAR(sim.calibration().soundSpeed, 2.0 * c0, 1e-9 * c0);
  EXPECT_DOUBLE_EQ(sim.liveParameters().stiffness, values.stiffness);
  sim.step();
  // The step is bounded by the speed of sound (CFL) in free fall.
  EXPECT_NEAR(sim.lastDt(), 0.5 * dt, 0.05 * dt);
}

// The incompressible solver reads gravity and viscosity each step as the weakly compressible
// one does; the equation of state's stiffness, which it does not use, leaves its step alone.
TEST(LiveParameters, UnderDfsphGravityTakesEffectAndStiffnessLeavesTheStepAlone) {
  Scene scene = fallingBlock();
  scene.fluid.solver = FluidSolver::Dfsph;
  Simulation sim(scene);
  sim.advanceTo(0.05);
  const double falling = meanVerticalVelocity(sim);
  EXPECT_NEAR(falling, -9.81 * 0.05, 0.02);
  LiveParameters values = sim.liveParameters();
  values.gravity = {0, 0, 0};
  values.stiffness *= 4.0;
  sim.setLiveParameters(values);
  sim.step();
  const double dt = sim.lastDt();
  sim.step();
  EXPECT_NEAR(sim.lastDt(), dt, 0.05 * dt);
  sim.advanceTo(0.1);
  EXPECT_NEAR(meanVerticalVelocity(sim), falling, 0.01);
}

TEST(LiveParameters, AValueOutOfRangeNamesTheKeyAndChangesNothing) {
  Simulation sim(fallingBlock());
  LiveParameters values = sim.liveParameters();
  const double viscosity = values.viscosity;
  values.viscosity = -1.0;
  values.gravity = {0, 0, 0};
  try {
    sim.setLiveParameters(values);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fluid.viscosity"), std::string::npos) << e.what();
  }
  EXPECT_DOUBLE_EQ(sim.liveParameters().viscosity, viscosity);
  EXPECT_DOUBLE_EQ(sim.liveParameters().gravity[1], -9.81);
}

TEST(SteerObject, AKinematicSphereGoesWhereItIsDraggedAndStays) {
  Scene scene = fallingBlock();
  ObjectDesc probe;
  probe.name = "probe";
  probe.motion = ObjectMotion::Kinematic;
  probe.shape.kind = ShapeKind::Sphere;
  probe.shape.center = {0.5, 0.5, 0.5};
  probe.shape.radius = 0.02;
  scene.objects.push_back(probe);
  Simulation sim(scene);
  sim.advanceTo(0.01);
  sim.steerObject("probe", {-0.1, 0.05, 0.0}, 0.02);
  sim.advanceTo(0.02);  // half way
  std::array<double, 3> c = sim.objectStats()[0].centreOfMass;
  EXPECT_NEAR(c[0], 0.45, 1e-3);
  EXPECT_NEAR(c[1], 0.525, 1e-3);
  sim.advanceTo(0.05);  // arrived, and held
  c = sim.objectStats()[0].centreOfMass;
  EXPECT_NEAR(c[0], 0.4, 1e-4);
  EXPECT_NEAR(c[1], 0.55, 1e-4);
  EXPECT_NEAR(c[2], 0.5, 1e-4);
  EXPECT_THROW(sim.steerObject("nothing", {0, 0, 0}, 0.1), InputError);
}

}  // namespace
}  // namespace sph
