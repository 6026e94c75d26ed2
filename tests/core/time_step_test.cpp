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

}  // namespace
}  // namespace sph
