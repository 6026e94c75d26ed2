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

}  // namespace
}  // namespace sph
