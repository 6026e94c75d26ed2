// With gravity off and no walls, only pair forces act: total linear momentum is constant.
#include <gtest/gtest.h>

#include <algorithm>
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

// A box periodic along every axis, filled with two layers sliding past each other and across
// the faces: every pair that meets across a face must push and rub exactly as any other, so
// the momentum stays what it was, no particle is lost, and no seam shows in the density.
Scene periodicShearLayers(FluidSolver solver) {
  Scene s;
  s.name = "periodic_shear";
  s.sourcePath = "periodic_shear (test)";
  s.gravity = {0, 0, 0};
  s.fluid.spacing = 0.01;
  s.fluid.solver = solver;
  s.fluid.kernel = KernelKind::CubicSpline;
  s.fluid.viscosity = 0.1;
  s.domain.box = {{0, 0, 0}, {0.1, 0.1, 0.1}};
  s.domain.periodic = {true, true, true};
  s.fluid.blocks.push_back({{{0, 0, 0}, {0.1, 0.05, 0.1}}, {0.5, 0.1, 0}, false, ""});
  s.fluid.blocks.push_back({{{0, 0.05, 0}, {0.1, 0.1, 0.1}}, {-0.3, 0, 0.2}, false, ""});
  s.calibration.maxExpectedSpeed = 0.6;
  return s;
}

class PeriodicMomentum : public ::testing::TestWithParam<std::tuple<Backend, FluidSolver>> {};

TEST_P(PeriodicMomentum, ShearedLayersInAPeriodicBoxKeepTheirMomentumAndEveryParticle) {
  const auto [backend, solver] = GetParam();
  SPH_SKIP_UNLESS_AVAILABLE(backend);
  Simulation sim(periodicShearLayers(solver), testing::on(backend));
  const Momentum before = momentumOf(sim);
  const double kinetic0 = sim.stats().kineticEnergy;
  double worstCompression = 0.0;
  while (sim.time() < 0.3) {  // each layer crosses the box's x faces at least once
    sim.step();
    worstCompression = std::max(worstCompression, sim.stats().maxDensityError);
  }
  const Momentum after = momentumOf(sim);
  EXPECT_EQ(sim.fluidCount(), sim.calibration().fluidParticles);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(after.p[a], before.p[a], 1e-5 * before.magnitudeSum) << "axis " << a;
  // The layers rubbed: viscosity took energy out, across the faces as well as inside.
  EXPECT_LT(sim.stats().kineticEnergy, 0.95 * kinetic0);
  // Every particle has a full neighbourhood, across the faces too: a seam would read low.
  EXPECT_LT(worstCompression, 0.03);
  EXPECT_GT(sim.stats().meanDensity, 0.99 * 1000.0);
  const ParticleFrame f = sim.frame(false);
  for (std::size_t i = 0; i < f.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      ASSERT_GE(f.position[3 * i + a], 0.0f);
      ASSERT_LT(f.position[3 * i + a], 0.1f);
    }
}

INSTANTIATE_TEST_SUITE_P(
    BackendsAndSolvers, PeriodicMomentum,
    ::testing::Combine(::testing::Values(Backend::Cpu, Backend::Cuda),
                       ::testing::Values(FluidSolver::Wcsph, FluidSolver::Dfsph)),
    [](const auto& info) {
      return std::string(std::get<0>(info.param) == Backend::Cuda ? "cuda" : "cpu") +
             (std::get<1>(info.param) == FluidSolver::Wcsph ? "_wcsph" : "_dfsph");
    });

}  // namespace
}  // namespace sph
