// A frame captured and taken later is the frame of the moment of capture, whatever the
// simulation did meanwhile (on the GPU the copy runs while the next steps do).
#include <gtest/gtest.h>

#include <string>

#include "backends.hpp"
#include "scene/scene_loader.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

class FrameCaptureTest : public ::testing::TestWithParam<Backend> {};

TEST_P(FrameCaptureTest, TakenLaterIsTheFrameAndStatsOfTheCapture) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  // Objects too: their particles are copied at the capture.
  const Scene scene = scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/artery_squeeze.json");
  Simulation sim(scene, testing::on(GetParam()));
  for (int i = 0; i < 20; ++i) sim.step();
  const ParticleFrame expectedFrame = sim.frame(false);
  const FrameStats expectedStats = sim.stats();

  FrameCapture capture = sim.capture();
  FrameCapture second = sim.capture();  // two in flight at once
  for (int i = 0; i < 20; ++i) sim.step();
  ParticleFrame frame;
  FrameStats stats;
  capture.take(frame, stats);

  EXPECT_EQ(frame.time, expectedFrame.time);
  EXPECT_EQ(frame.step, expectedFrame.step);
  EXPECT_EQ(frame.id, expectedFrame.id);
  EXPECT_EQ(frame.position, expectedFrame.position);
  EXPECT_EQ(frame.velocity, expectedFrame.velocity);
  EXPECT_EQ(frame.density, expectedFrame.density);
  EXPECT_EQ(frame.kind, expectedFrame.kind);
  EXPECT_EQ(frame.surface, expectedFrame.surface);
  EXPECT_EQ(stats.steps, expectedStats.steps);
  EXPECT_EQ(stats.fluidCount, expectedStats.fluidCount);
  EXPECT_EQ(stats.kineticEnergy, expectedStats.kineticEnergy);
  EXPECT_EQ(stats.maxDensityError, expectedStats.maxDensityError);
  EXPECT_EQ(stats.surfaceCount, expectedStats.surfaceCount);
  ASSERT_EQ(stats.objects.size(), expectedStats.objects.size());
  EXPECT_EQ(stats.objects[0].centreOfMass, expectedStats.objects[0].centreOfMass);

  ParticleFrame other;
  FrameStats otherStats;
  second.take(other, otherStats);
  EXPECT_EQ(other.position, expectedFrame.position);
  // And the simulation did move on.
  EXPECT_NE(sim.frame(false).position, expectedFrame.position);
}

SPH_ON_EVERY_BACKEND(FrameCaptureTest);

}  // namespace
}  // namespace sph
