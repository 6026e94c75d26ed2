// The time-step guard (src/sim/time_step_guard.cpp): a step never passes the time it is asked
// to stop at, and lands on it exactly rather than leave a sliver for later, so that runs stopped
// at a frame's time and runs stepping through it take the same steps.
#include <gtest/gtest.h>

#include <vector>

#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

Scene fixedStepTank(double dt) {
  Scene scene = testing::restingTank(0.02, 0.1, 0.1);
  scene.time.fixedDt = dt;
  return scene;
}

// With 1.5 steps left, a whole step would leave half a step: two steps of 0.75 land on it.
TEST(TimeStepGuard, LandsOnTheEndWithoutASliver) {
  const double dt = 1.0 / 8192.0;  // a power of two: its sums are exact
  Simulation sim(fixedStepTank(dt));
  const double until = 1.5 * dt;
  std::vector<double> steps;
  while (sim.time() < until) {
    sim.step(until);
    steps.push_back(sim.lastDt());
  }
  EXPECT_EQ(sim.time(), until);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_DOUBLE_EQ(steps[0], 0.75 * dt);
  EXPECT_DOUBLE_EQ(steps[1], 0.75 * dt);
}

// Stopping at a time the steps would have passed through changes the steps after it: what a
// run that ends between two frames must not checkpoint (apps/sph/run_command.cpp).
TEST(TimeStepGuard, AStopChangesTheStepsAfterIt) {
  const double dt = 1.0 / 8192.0;  // a power of two: its sums are exact
  Simulation through(fixedStepTank(dt)), stopped(fixedStepTank(dt));
  through.advanceTo(4.0 * dt);
  stopped.advanceTo(1.5 * dt);
  stopped.advanceTo(4.0 * dt);
  EXPECT_EQ(through.time(), stopped.time());
  EXPECT_EQ(through.stepCount(), 4u);
  EXPECT_EQ(stopped.stepCount(), 5u);  // 0.75, 0.75, then 1, 0.75, 0.75 (1.5 left at 2.5)
}

}  // namespace
}  // namespace sph
