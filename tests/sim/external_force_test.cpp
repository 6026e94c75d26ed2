// External accelerations set by an embedding application act like a body force, per particle.
#include <gtest/gtest.h>

#include <stdexcept>

#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

Scene freeBlock() {
  Scene s;
  s.sourcePath = "free block (test)";
  s.gravity = {0, 0, 0};
  s.calibration.speedOfSound = 10.0;
  s.fluid.spacing = 0.01;
  s.domain.box = {{-1, -1, -1}, {1, 1, 1}};
  s.fluid.blocks.push_back({{{0, 0, 0}, {0.05, 0.05, 0.05}}, {0, 0, 0}, false, ""});
  return s;
}

TEST(ExternalForce, AcceleratesTheFluidAsABodyForce) {
  Simulation sim(freeBlock());
  const std::size_t n = sim.calibration().fluidParticles;
  std::vector<float> push(3 * n, 0.0f);
  for (std::size_t i = 0; i < n; ++i) push[3 * i] = 2.0f;  // 2 m/s² along x, every particle
  sim.setExternalAcceleration(push);
  sim.advanceTo(0.05);
  // Pair forces cancel in the sum: the mean velocity is exactly a t.
  const ParticleFrame f = sim.frame(false);
  double meanVx = 0.0, meanVy = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    meanVx += f.velocity[3 * i] / double(f.size());
    meanVy += f.velocity[3 * i + 1] / double(f.size());
  }
  EXPECT_NEAR(meanVx, 0.1, 1e-5);
  EXPECT_NEAR(meanVy, 0.0, 1e-6);

  sim.setExternalAcceleration({});  // removed: the block coasts
  sim.advanceTo(0.1);
  const ParticleFrame g = sim.frame(false);
  double coast = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i) coast += g.velocity[3 * i] / double(g.size());
  EXPECT_NEAR(coast, 0.1, 1e-5);
}

TEST(ExternalForce, WrongSizeIsRefused) {
  Simulation sim(freeBlock());
  EXPECT_THROW(sim.setExternalAcceleration(std::vector<float>(5, 0.0f)), std::invalid_argument);
}

}  // namespace
}  // namespace sph
