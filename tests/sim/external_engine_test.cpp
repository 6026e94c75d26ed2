// An object engine of the user's own, attached through the exchange
// (Simulation::attachObjectEngine): the fluid pushes its objects and is pushed back alike, and
// what breaks the exchange's rules is refused.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "backends.hpp"
#include "fluid_momentum.hpp"
#include "sph/object_exchange.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

// The test's own engine: one rigid box that translates under the forces it takes, the
// particles of its faces published at one spacing.
class TranslatingBox {
 public:
  TranslatingBox(Vec3 centre, Vec3 half, float spacing, double density)
      : centre_(centre), radius_(0.5f * spacing) {
    const int n[3] = {int(std::lround(2 * half.x / spacing)),
                      int(std::lround(2 * half.y / spacing)),
                      int(std::lround(2 * half.z / spacing))};
    for (int i = 0; i <= n[0]; ++i)
      for (int j = 0; j <= n[1]; ++j)
        for (int k = 0; k <= n[2]; ++k) {
          const int at[3] = {i, j, k};
          float normal[3] = {0, 0, 0};
          bool onFace = false;
          for (int a = 0; a < 3; ++a) {
            if (at[a] == 0) normal[a] = -1.0f, onFace = true;
            if (at[a] == n[a]) normal[a] = 1.0f, onFace = true;
          }
          if (!onFace) continue;
          const Vec3 nrm{normal[0], normal[1], normal[2]};
          offset_.push_back(
              Vec3{-half.x + i * spacing, -half.y + j * spacing, -half.z + k * spacing});
          normal_.push_back(nrm * (1.0f / length(nrm)));
        }
    mass_ = density * 8.0 * half.x * half.y * half.z;
  }

  std::size_t particles() const { return offset_.size(); }
  double mass() const { return mass_; }
  Vec3 velocity() const { return velocity_; }

  void publish(ObjectExchange& exchange, double time) const {
    ObjectSurface& s = exchange.back();
    s.clear();
    for (std::size_t k = 0; k < offset_.size(); ++k)
      s.add(centre_ + offset_[k], velocity_, radius_, normal_[k], std::uint32_t(k), 0, false);
    s.time = time;
    exchange.publish();
  }

  // The forces the fluid deposited since the last call, over the time they span.
  void step(ObjectExchange& exchange) {
    std::vector<Vec3> force;
    const double span = exchange.takeForces(force);
    Vec3 total{0, 0, 0};
    for (const Vec3& f : force) total += f;
    velocity_ += total * float(span / mass_);
    centre_ += velocity_ * float(span);
  }

 private:
  std::vector<Vec3> offset_, normal_;
  Vec3 centre_;
  Vec3 velocity_{0, 0, 0};
  float radius_;
  double mass_ = 0.0;
};

Scene blockOnly() {
  Scene s;
  s.name = "block_hits_attached_body";
  s.sourcePath = "block_hits_attached_body (test)";
  s.gravity = {0, 0, 0};
  s.fluid.spacing = 0.01;
  s.fluid.viscosity = 0.1;
  s.domain.box = {{-1, -1, -1}, {1, 1, 1}};
  FluidBlock block;
  block.box = {{-0.1, -0.05, -0.05}, {0.0, 0.05, 0.05}};
  block.velocity = {1.0, 0.1, 0.0};
  s.fluid.blocks.push_back(block);
  return s;
}

using testing::fluidMomentum;

class ExternalEngine : public ::testing::TestWithParam<Backend> {};

// Newton's third law through the exchange: the fluid block hits the attached body, and fluid +
// body keep their momentum; the body moved off, and the fluid's force on it is reported.
TEST_P(ExternalEngine, FluidAndAttachedBodyConserveMomentum) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Simulation sim(blockOnly(), testing::on(GetParam()));
  TranslatingBox body(Vec3{0.06f, 0.01f, 0.0f}, Vec3{0.03f, 0.04f, 0.03f}, 0.01f, 800.0);
  auto exchange = std::make_shared<ObjectExchange>(body.particles());
  body.publish(*exchange, 0.0);
  sim.attachObjectEngine(exchange);
  const std::array<double, 4> before = fluidMomentum(sim);
  double largestForce = 0.0;
  while (sim.time() < 0.15) {
    sim.step();
    body.step(*exchange);
    body.publish(*exchange, sim.time());
    ASSERT_EQ(sim.objectStats().size(), 1u);
    largestForce = std::max(largestForce, std::abs(sim.objectStats()[0].fluidForce[0]));
  }
  const std::array<double, 4> after = fluidMomentum(sim);
  const Vec3 v = body.velocity();
  const double bodyMomentum[3] = {body.mass() * v.x, body.mass() * v.y, body.mass() * v.z};
  EXPECT_GT(v.x, 0.05) << "the fluid did not push the body";
  EXPECT_GT(largestForce, 0.0);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(after[a] + bodyMomentum[a], before[a], 1e-5 * before[3]) << "axis " << a;
  EXPECT_EQ(sim.fluidCount(), sim.calibration().fluidParticles);
}

SPH_ON_EVERY_BACKEND(ExternalEngine);

TEST(ExternalEngineRules, WhatBreaksTheExchangeIsRefused) {
  Simulation sim(blockOnly());
  EXPECT_THROW(sim.attachObjectEngine(nullptr), std::invalid_argument);
  TranslatingBox body(Vec3{0.06f, 0.01f, 0.0f}, Vec3{0.03f, 0.04f, 0.03f}, 0.01f, 800.0);
  // One handle fewer than the box publishes: its last particle's handle is past the count.
  ObjectExchange tooFew(body.particles() - 1);
  EXPECT_THROW(body.publish(tooFew, 0.0), std::out_of_range);
  // Particles 3 cm across: their contact reach passes the fluid's support radius (2 cm).
  TranslatingBox coarse(Vec3{0.06f, 0.01f, 0.0f}, Vec3{0.03f, 0.03f, 0.03f}, 0.06f, 800.0);
  auto exchange = std::make_shared<ObjectExchange>(coarse.particles());
  coarse.publish(*exchange, 0.0);
  sim.attachObjectEngine(exchange);
  EXPECT_THROW(sim.attachObjectEngine(exchange), std::logic_error);
  EXPECT_THROW(sim.step(), std::invalid_argument);
  std::ostringstream state;
  EXPECT_THROW(sim.saveState(state), std::logic_error);
}

}  // namespace
}  // namespace sph
