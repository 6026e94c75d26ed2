// The incompressible solver's density solve (dfsph_solve.hpp), both walks: it undoes a
// compression without making momentum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid_fixture.hpp"

namespace sph::fluid {
namespace {

using namespace testing;

class DensitySolveStage : public ::testing::TestWithParam<NeighborWalk> {};

TEST_P(DensitySolveStage, TheDensitySolveUndoesACompressionWithoutMakingMomentum) {
  const Lattice lattice = jitteredLattice(0.99f, 0.05f, 0.0f, 13);
  Fluid fluid(lattice, KernelKind::CubicSpline, ViscosityModel::Artificial);
  fluid.params.pressureForces = false;
  fluid.densityPass(GetParam());
  prepareSolver(fluid.particles);
  SolverSettings settings;
  settings.warmStart = false;
  settings.minNeighbours = 20;
  // No iterations: only the first pass, which finds the step's factors.
  CoarsePressure coarse;
  solve(fluid.particles, fluid.grid, fluid.walls, fluid.objects, fluid.params, settings,
        SolverTarget::NoDivergence, 0.0f, GetParam(), coarse);
  settings.tolerance = 1e-4f;
  settings.maxIterations = 200;
  const float dt = 1e-3f;
  const SolverReport report =
      solve(fluid.particles, fluid.grid, fluid.walls, fluid.objects, fluid.params, settings,
            SolverTarget::RestDensity, dt, GetParam(), coarse);
  EXPECT_TRUE(report.converged);
  EXPECT_GT(report.iterations, 1);

  // The solve's accelerations sum to nothing: every pair pushes both ways.
  const Imbalance imbalance = accelerationImbalance(fluid.particles);
  ASSERT_GT(imbalance.magnitude, 1.0);
  for (double share : imbalance.axis) EXPECT_LT(share, 1e-6);

  // Moved by the step the solve predicted over, the block's inner particles (three spacings
  // and more from its faces) are no longer compressed: 3.6 % before on average. The step's
  // density is predicted linearly, and a solve that only pushes does not take back what it
  // overshoots (measured after it: the mean at -0.6 %, the most compressed at +0.6 %).
  struct Errors {
    double mean = 0.0, largest = -1.0;
  };
  const auto innerErrors = [&](const Fluid& f) {
    const std::vector<float> density = f.byId(f.particles.density);
    Errors e;
    int count = 0;
    for (std::size_t i = 0; i < lattice.position.size(); ++i) {
      const int a = int(i / 100), b = int(i / 10 % 10), c = int(i % 10);
      if (std::min({a, b, c}) < 3 || std::max({a, b, c}) > 6) continue;
      const double error = density[i] / kRestDensity - 1.0;
      e.mean += error;
      e.largest = std::max(e.largest, error);
      ++count;
    }
    e.mean /= count;
    return e;
  };
  const Errors before = innerErrors(fluid);
  Lattice moved = lattice;
  const std::vector<Vec4> a = fluid.byId(fluid.particles.acceleration);
  for (std::size_t i = 0; i < moved.position.size(); ++i)
    moved.position[i] = moved.position[i] + xyz(a[i]) * (dt * dt);
  Fluid after(moved, KernelKind::CubicSpline, ViscosityModel::Artificial);
  after.densityPass(GetParam());
  const Errors remaining = innerErrors(after);
  EXPECT_GT(before.mean, 0.03);
  EXPECT_LT(remaining.largest, 0.25 * before.mean) << "from " << before.mean;
  EXPECT_LT(std::abs(remaining.mean), 0.25 * before.mean) << "from " << before.mean;
}

SPH_BOTH_WALKS(DensitySolveStage);

}  // namespace
}  // namespace sph::fluid
