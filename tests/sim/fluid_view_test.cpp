// Simulation::fluidView: the CPU backend's arrays read in place are the particles a frame
// copies, in the engine's order; the CUDA backend, whose particles live on the GPU, has none.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "backends.hpp"
#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

class FluidViewTest : public ::testing::TestWithParam<Backend> {};

TEST_P(FluidViewTest, TheArraysInPlaceAreTheFramesParticles) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Simulation sim(testing::restingTank(0.02, 0.1, 0.1), testing::on(GetParam()));
  for (int k = 0; k < 5; ++k) sim.step();
  const FluidView view = sim.fluidView();
  if (GetParam() == Backend::Cuda) {
    EXPECT_FALSE(view);
    EXPECT_EQ(view.count, 0u);
    return;
  }
  ASSERT_TRUE(view);
  EXPECT_EQ(view.step, sim.stepCount());
  const ParticleFrame frame = sim.frame(false);
  ASSERT_EQ(view.count, frame.size());
  std::vector<std::size_t> byId(view.count);
  std::iota(byId.begin(), byId.end(), std::size_t{0});
  std::sort(byId.begin(), byId.end(),
            [&](std::size_t a, std::size_t b) { return view.id[a] < view.id[b]; });
  // The engine's order is the grid's, not the ids' (else a view would be a frame).
  EXPECT_FALSE(std::is_sorted(view.id, view.id + view.count));
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const std::size_t k = byId[i];
    ASSERT_EQ(view.id[k], frame.id[i]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(view.position[FluidView::kVectorStride * k + c], frame.position[3 * i + c]);
      EXPECT_EQ(view.velocity[FluidView::kVectorStride * k + c], frame.velocity[3 * i + c]);
    }
    EXPECT_EQ(view.density[k], frame.density[i]);
    EXPECT_EQ(view.pressure[k], frame.pressure[i]);
  }
}

SPH_ON_EVERY_BACKEND(FluidViewTest);

}  // namespace
}  // namespace sph
