// A blow-up stops the run with the step, the particle and the quantity, and keeps the last
// good state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scene_builders.hpp"
#include "sim/scene_size.hpp"
#include "sph/core/constants.hpp"
#include "sph/error.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

TEST(Failure, BlowUpNamesStepParticleAndQuantity) {
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.time.fixedDt = 0.004;  // ten times the CFL limit
  Simulation sim(scene);
  bool failed = false;
  try {
    for (int i = 0; i < 500; ++i) sim.step();
  } catch (const SimulationFailure& failure) {
    failed = true;
    const std::string message = failure.what();
    EXPECT_NE(message.find("step " + std::to_string(failure.step())), std::string::npos);
    EXPECT_NE(message.find("particle " + std::to_string(failure.particleId())), std::string::npos);
    EXPECT_NE(message.find(failure.quantity()), std::string::npos);
    EXPECT_LT(failure.particleId(), sim.calibration().fluidParticles);
    EXPECT_EQ(failure.step(), sim.stepCount());
  }
  ASSERT_TRUE(failed) << "an unstable time step must be detected";
  // The state is the last good one: finite everywhere.
  const ParticleFrame f = sim.frame(false);
  for (float x : f.position) ASSERT_TRUE(std::isfinite(x));
  for (float v : f.velocity) ASSERT_TRUE(std::isfinite(v));
}

// A stiffness far beyond the calibration's with a fixed step once threw every particle out of
// the domain at 7e8 m/s, and the run reported itself completed.
TEST(Failure, RunawaySpeedStopsTheRunNamingTheFastestParticle) {
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.calibration.stiffness = 1e12;
  scene.time.fixedDt = 0.001;
  Simulation sim(scene);
  try {
    for (int i = 0; i < 100; ++i) sim.step();
    FAIL() << "a run at thousands of m/s must fail";
  } catch (const SimulationFailure& failure) {
    EXPECT_EQ(failure.quantity(), "speed");
    const std::string message = failure.what();
    EXPECT_NE(message.find("particle " + std::to_string(failure.particleId())), std::string::npos)
        << message;
    EXPECT_NE(message.find("past ten times the speed of sound"), std::string::npos) << message;
    EXPECT_LT(failure.particleId(), sim.calibration().fluidParticles);
  }
  EXPECT_LE(sim.stepCount(), 5u);
}

// failure.max_speed: a scene's own bound on speed stops a run that the default (ten times the
// speed of sound) would let go on. A column 0.1 m high collapsing across a tank three times as
// wide reaches 1 m/s within 0.1 s.
TEST(Failure, ASpeedPastTheScenesBoundStopsTheRun) {
  Scene scene = testing::restingTank(0.01, 0.3, 0.1);
  scene.fluid.blocks[0].box.max = {0.1, 0.1, 0.1};
  scene.failure.maxSpeed = 0.5;
  Simulation sim(scene);
  try {
    sim.advanceTo(0.1);
    FAIL() << "the column's fall passes 0.5 m/s";
  } catch (const SimulationFailure& failure) {
    EXPECT_EQ(failure.quantity(), "speed");
    const std::string message = failure.what();
    EXPECT_NE(message.find("past failure.max_speed (0.5 m/s)"), std::string::npos) << message;
  }
  EXPECT_GT(sim.time(), 0.0);
  const ParticleFrame frame = sim.frame(false);
  float fastest = 0.0f;
  for (std::size_t i = 0; i < frame.size(); ++i)
    fastest = std::max(fastest, std::hypot(frame.velocity[3 * i], frame.velocity[3 * i + 1],
                                           frame.velocity[3 * i + 2]));
  // The run stopped at the first step that found a particle past the bound, and kept that state.
  EXPECT_GT(fastest, 0.5f);
  EXPECT_LT(fastest, 0.55f);
}

// --set fluid.spacing=0.0001 on the dam break once grew to 4.6 GB and ended in bad_alloc.
TEST(Failure, ASceneLargerThanTheMachineIsRefusedBeforeAnythingIsMade) {
  Scene scene = testing::restingTank(1e-5, 0.1, 0.1);  // 1e12 particles
  try {
    Simulation sim(scene);
    FAIL() << "a scene of 1e12 particles was built";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("resting_tank (test): fluid.spacing: the scene would make 1e+12 "
                           "fluid"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("GB of memory, more than this machine's"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(sim::refuseIfTooLarge(testing::restingTank(0.01, 0.1, 0.1), 1e7));
  EXPECT_THROW(sim::refuseIfTooLarge(testing::restingTank(0.01, 0.1, 0.1), 1e5), InputError);
  // The scene's own limits, below the machine's: 1,000 fluid particles and their walls.
  Scene limited = testing::restingTank(0.01, 0.1, 0.1);
  limited.limits.maxParticles = 1000;
  const auto refusal = [&] {
    try {
      sim::refuseIfTooLarge(limited, 1e12);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal().find("limits.max_particles: the scene would make 1e+03 fluid"),
            std::string::npos)
      << refusal();
  limited.limits.maxParticles = 1e5;
  EXPECT_EQ(refusal(), "accepted");
  limited.limits.maxMemoryGb = 1e-4;  // 100 kB
  EXPECT_NE(refusal().find("limits.max_memory_gb"), std::string::npos) << refusal();
  // Objects count too: a sphere a kilometre across sampled at a centimetre.
  Scene huge = testing::restingTank(0.01, 0.1, 0.1);
  ObjectDesc ball;
  ball.shape.kind = ShapeKind::Sphere;
  ball.shape.radius = 500.0;
  huge.objects.push_back(ball);
  try {
    sim::refuseIfTooLarge(huge, 1e10);
    FAIL() << "a sphere of 1e10 particles passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(": objects: the scene would make"), std::string::npos)
        << e.what();
  }
  // An emitter's particles count for what it puts in over the run, up to what the domain holds.
  Scene pumped = testing::restingTank(0.01, 0.1, 0.1);
  EmitterDesc e;
  e.center = {0.05, 0.05, 0.05};
  e.radius = 0.05;
  e.speed = 1.0;
  pumped.emitters.push_back(e);
  pumped.time.duration = 1.0;
  const double before = sim::estimateSize(testing::restingTank(0.01, 0.1, 0.1)).fluidParticles;
  const double emitted = sim::estimateSize(pumped).fluidParticles - before;
  EXPECT_NEAR(emitted, kPi * 25.0 * 100.0, 1.0);  // (π 5²) a layer, 100 layers
  pumped.time.duration = 1e6;
  const AxisBox& domain = pumped.domain.box;
  double domainCells = 1.0;
  for (int a = 0; a < 3; ++a) domainCells *= std::round((domain.max[a] - domain.min[a]) / 0.01);
  EXPECT_EQ(sim::estimateSize(pumped).fluidParticles - before, domainCells);
}

TEST(Failure, UnderivableSoundSpeedIsAnInputError) {
  Scene scene = testing::collidingBlocks(PressureForm::Symmetric);
  for (auto& block : scene.fluid.blocks) block.velocity = {0, 0, 0};
  EXPECT_THROW(Simulation{scene}, InputError);
  scene.calibration.speedOfSound = 10.0;
  EXPECT_NO_THROW(Simulation{scene});
}

}  // namespace
}  // namespace sph
