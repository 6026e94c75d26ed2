#include "sph/core/time_step.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sph {
namespace {

TEST(TimeStep, SpringStepIsOneOverItsAngularFrequency) {
  // 1 g on 40 N/m scaled by 10: ω = sqrt(400 / 0.001) = 632.5 rad/s.
  EXPECT_NEAR(springTimeStep(0.001, 40.0, 10.0), 1.0 / std::sqrt(400.0 / 0.001), 1e-15);
  EXPECT_EQ(springTimeStep(0.001, 0.0, 10.0), HUGE_VAL);
}

TEST(TimeStep, TravelStepKeepsMotionUnderTheDistance) {
  EXPECT_DOUBLE_EQ(travelTimeStep(0.0005, 2.0), 0.00025);
  EXPECT_EQ(travelTimeStep(0.0005, 0.0), HUGE_VAL);
}

// The incompressible solver's step: no particle crosses more than cfl·h; at rest, no bound.
TEST(TimeStep, FlowStepFollowsTheFastestParticle) {
  EXPECT_DOUBLE_EQ(flowTimeStep(0.4, 0.02, 2.0), 0.004);
  EXPECT_DOUBLE_EQ(flowTimeStep(0.4, 0.02, 4.0), 0.002);
  EXPECT_EQ(flowTimeStep(0.4, 0.02, 0.0), HUGE_VAL);
  // The weakly compressible step carries the speed of sound as well: ten times smaller here.
  EXPECT_LT(cflTimeStep(0.4, 0.02, 20.0, 2.0), 0.1 * flowTimeStep(0.4, 0.02, 2.0));
}

// Sound and flow together cross exactly cfl·h in the step, whatever h and the speeds.
TEST(TimeStep, CflStepLetsSoundCrossAFractionOfH) {
  for (double h : {0.004, 0.02})
    for (double c : {5.0, 20.0})
      for (double v : {0.0, 2.0}) {
        const double dt = cflTimeStep(0.4, h, c, v);
        EXPECT_NEAR((c + v) * dt, 0.4 * h, 1e-15) << "h " << h << " c " << c << " v " << v;
      }
  EXPECT_GT(cflTimeStep(0.4, 0.02, 20.0, 0.0), cflTimeStep(0.4, 0.02, 20.0, 2.0));
}

// Starting from rest under its largest acceleration a, a particle moves a dt² / 2 in the step:
// factor² / 2 of h. Without acceleration, no bound.
TEST(TimeStep, ForceStepKeepsAnAcceleratedParticleWithinAFractionOfH) {
  const double h = 0.02, factor = 0.25;
  for (double a : {9.81, 1000.0}) {
    const double dt = forceTimeStep(factor, h, a);
    EXPECT_NEAR(0.5 * a * dt * dt, 0.5 * factor * factor * h, 1e-15) << "a " << a;
  }
  EXPECT_EQ(forceTimeStep(factor, h, 0.0), HUGE_VAL);
}

// Explicit diffusion over the step spreads momentum by sqrt(ν dt) = sqrt(factor) h: ν dt / h² is
// the factor. An inviscid fluid has no bound.
TEST(TimeStep, ViscousStepHoldsTheDiffusionNumber) {
  const double h = 0.002, factor = 0.125;
  for (double nu : {1e-6, 1e-3}) {
    const double dt = viscousTimeStep(factor, h, nu);
    EXPECT_NEAR(nu * dt / (h * h), factor, 1e-12) << "nu " << nu;
  }
  EXPECT_EQ(viscousTimeStep(factor, h, 0.0), HUGE_VAL);
  // A no-slip wall (friction 2) doubles the diffusion beside it, and halves the step; a
  // friction under 1 leaves the fluid's own bound.
  EXPECT_DOUBLE_EQ(viscousTimeStep(factor, h, 1e-3, 2.0), 0.5 * viscousTimeStep(factor, h, 1e-3));
  EXPECT_DOUBLE_EQ(viscousTimeStep(factor, h, 1e-3, 0.5), viscousTimeStep(factor, h, 1e-3));
}

// The step is the shortest of the bounds: sound (or, for an incompressible solver, the flow
// alone), acceleration, viscosity, what the caller adds and the scene's cap.
TEST(TimeStep, TheLongestStepIsTheShortestBound) {
  StepLimits l;
  l.h = 0.02;
  l.soundSpeed = 20.0;
  l.kinematicViscosity = 1e-6;
  l.maxDt = 1e-2;
  EXPECT_DOUBLE_EQ(longestStep(l, 1.0, 9.81), cflTimeStep(l.cfl, l.h, 20.0, 1.0));
  EXPECT_DOUBLE_EQ(longestStep(l, 1.0, 9.81, 1e-5), 1e-5);
  EXPECT_DOUBLE_EQ(longestStep(l, 0.0, 1e6), forceTimeStep(l.forceFactor, l.h, 1e6));
  l.kinematicViscosity = 1.0;
  EXPECT_DOUBLE_EQ(longestStep(l, 1.0, 9.81), viscousTimeStep(l.viscousFactor, l.h, 1.0));
  l.kinematicViscosity = 1e-6;
  l.followsFlow = true;  // no sound: the flow, then gravity, then the cap
  EXPECT_DOUBLE_EQ(longestStep(l, 1.0, 0.0), flowTimeStep(l.cfl, l.h, 1.0));
  EXPECT_DOUBLE_EQ(longestStep(l, 0.0, 100.0), forceTimeStep(l.forceFactor, l.h, 100.0));
  EXPECT_DOUBLE_EQ(longestStep(l, 0.0, 0.0), l.maxDt);
}

}  // namespace
}  // namespace sph
