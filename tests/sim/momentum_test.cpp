// With gravity off and no walls, only pair forces act: total linear momentum is constant.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "backends.hpp"
#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

struct Momentum {
  double p[3] = {0, 0, 0};
  double magnitudeSum = 0;  // Σ m|v|, the scale rounding errors are measured against
};

Momentum momentumOf(const Simulation& sim) {
  const ParticleFrame f = sim.frame(false);
  const double m = sim.calibration().mass;
  Momentum out;
  for (std::size_t i = 0; i < f.size(); ++i) {
    double speed2 = 0;
    for (int a = 0; a < 3; ++a) {
      out.p[a] += m * f.velocity[3 * i + a];
      speed2 += double(f.velocity[3 * i + a]) * f.velocity[3 * i + a];
    }
    out.magnitudeSum += m * std::sqrt(speed2);
  }
  return out;
}

class MomentumConservation : public ::testing::TestWithParam<std::tuple<Backend, PressureForm>> {};

TEST_P(MomentumConservation, ConstantOverAThousandSteps) {
  const auto [backend, form] = GetParam();
  SPH_SKIP_UNLESS_AVAILABLE(backend);
  Simulation sim(testing::collidingBlocks(form), testing::on(backend));
  const Momentum before = momentumOf(sim);
  const double maxKinetic0 = sim.stats().kineticEnergy;
  for (int i = 0; i < 1000; ++i) sim.step();
  const Momentum after = momentumOf(sim);
  // The blocks did collide: kinetic energy went into pressure and viscosity.
  EXPECT_LT(sim.stats().kineticEnergy, 0.9 * maxKinetic0);
  EXPECT_EQ(sim.fluidCount(), sim.calibration().fluidParticles);
  for (int a = 0; a < 3; ++a) {
    // Float rounding only: a millionth of the momentum in play per axis.
    EXPECT_NEAR(after.p[a], before.p[a], 1e-6 * before.magnitudeSum) << "axis " << a;
  }
}

INSTANTIATE_TEST_SUITE_P(
    BackendsAndPressureForms, MomentumConservation,
    ::testing::Combine(::testing::Values(Backend::Cpu, Backend::Cuda),
                       ::testing::Values(PressureForm::Symmetric, PressureForm::Paper)),
    [](const auto& info) {
      return std::string(std::get<0>(info.param) == Backend::Cuda ? "cuda" : "cpu") +
             (std::get<1>(info.param) == PressureForm::Symmetric ? "_symmetric" : "_paper");
    });

}  // namespace
}  // namespace sph
