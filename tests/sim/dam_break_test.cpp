// The dam break against Martin & Moyce (1952), square column: the surge front position Z(T)
// follows the experiment before the front reaches the far wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "backends.hpp"
#include "sph/simulation.hpp"
#include "test_data.hpp"

namespace sph {
namespace {

struct FrontPoint {
  double T, Z;
};

std::vector<FrontPoint> readMartinMoyce() {
  return testing::readTestData<FrontPoint>("martin_moyce_1952_square_front.csv");
}

// A column a = 0.1 m of 20 × 20 particles, 10 deep, in a tank 5.5 a long with 2 wall layers.
Scene damBreak(double a) {
  const double d = a / 20.0;
  Scene s;
  s.name = "dam_break_test";
  s.sourcePath = "dam_break (test)";
  s.fluid.spacing = d;
  s.fluid.viscosity = 0.02;  // as scenes/dam_break.json
  s.fluid.wallFriction = 1.0;
  s.domain.box = {{-0.05, -0.05, -0.05}, {5.5 * a + 0.05, 2.0 * a, 0.5 * a + 0.05}};
  // Released from the lattice at rest, without hydrostatic pre-compression: the pressure builds
  // within a few acoustic times (H / c0 = 7 ms), about as the experiment's gate opened. Started
  // hydrostatic, the front leads the T = 0.62 point by 11 % and the others by at most 8 %.
  s.fluid.blocks.push_back({{{0, 0, 0}, {a, a, 0.5 * a}}, {0, 0, 0}, false, ""});
  s.walls.push_back(WallDesc::tank({{0, 0, 0}, {5.5 * a, 1.5 * a, 0.5 * a}}, 2, false));
  return s;
}

double frontPosition(const Simulation& sim) {
  const ParticleFrame f = sim.frame(false);
  double front = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) front = std::max(front, double(f.position[3 * i]));
  return front + 0.5 * sim.calibration().spacing;  // the particle's extent, not its centre
}

class DamBreak : public ::testing::TestWithParam<Backend> {};

void expectFrontFollowsMartinAndMoyce(Backend backend, FluidSolver solver) {
  const auto experiment = readMartinMoyce();
  ASSERT_GE(experiment.size(), 15u) << "test data missing";
  const double a = 0.1, g = 9.81;
  Scene scene = damBreak(a);
  scene.fluid.solver = solver;
  // Under the sanitizers at twice the spacing, an eighth of the particles and half the steps.
  if (testing::kSanitized) scene.fluid.spacing *= 2.0;
  Simulation sim(scene, testing::on(backend));
  double sumError = 0.0, largestError = 0.0;
  int compared = 0;
  for (const FrontPoint& p : experiment) {
    if (p.T > 3.0) break;
    // Under the sanitizers (a tenth of the speed) the collapse's first steps are a memory
    // check; the comparison is the Release build's.
    if (testing::kSanitized && p.T > 0.8) return;
    sim.advanceTo(p.T * std::sqrt(a / g));
    const double Z = frontPosition(sim) / a;
    const double error = (Z - p.Z) / p.Z;
    // Stated tolerance: 10 % in Z for 0.8 ≤ T ≤ 3 (the far wall is at Z = 5.5); 12 % for the two
    // points before, while the experiment's gate was still opening (measured: +6 % and +10.5 %).
    // It holds at this resolution only: refined, every model's front leads the experiment's by
    // 8-10 % (docs/validation.md, "The surge front at finer resolution").
    const double tolerance = p.T < 0.8 ? 0.12 : 0.10;
    EXPECT_LT(std::abs(error), tolerance)
        << "T = " << p.T << ": Z = " << Z << ", experiment " << p.Z;
    std::printf("    T %.2f: Z %.3f, experiment %.2f (%+.1f %%)\n", p.T, Z, p.Z, 100.0 * error);
    sumError += std::abs(error);
    largestError = std::max(largestError, std::abs(error));
    ++compared;
  }
  std::printf(
      "  surge front against Martin & Moyce, %d points T <= 3: mean |error| %.1f %%, "
      "largest %.1f %%\n",
      compared, 100.0 * sumError / std::max(compared, 1), 100.0 * largestError);
  EXPECT_GE(compared, 15);
  EXPECT_LT(sumError / compared, 0.05) << "mean relative error in Z";
  EXPECT_EQ(sim.fluidCount(), sim.calibration().fluidParticles) << "no particle may leave";
}

TEST_P(DamBreak, SurgeFrontFollowsMartinAndMoyce) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  expectFrontFollowsMartinAndMoyce(GetParam(), FluidSolver::Wcsph);
}

TEST_P(DamBreak, DfsphSurgeFrontFollowsMartinAndMoyce) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  expectFrontFollowsMartinAndMoyce(GetParam(), FluidSolver::Dfsph);
}

TEST_P(DamBreak, PbfSurgeFrontFollowsMartinAndMoyce) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  expectFrontFollowsMartinAndMoyce(GetParam(), FluidSolver::Pbf);
}

SPH_ON_EVERY_BACKEND(DamBreak);

}  // namespace
}  // namespace sph
