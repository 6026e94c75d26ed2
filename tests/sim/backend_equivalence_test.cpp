// The same scene on the CPU and on the GPU, for each fluid solver: after a dam break's first
// steps the positions and densities agree within a stated tolerance (float sums in another
// order, not another method).
#include <gtest/gtest.h>

#include <cmath>

#include "backends.hpp"
#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

// A column against one wall: it collapses.
Scene collapsingColumn(FluidSolver solver) {
  Scene scene = testing::restingTank(0.01, 0.2, 0.1);
  scene.fluid.blocks[0].box.max[0] = 0.05;
  scene.fluid.solver = solver;
  if (solver == FluidSolver::Dfsph) scene.fluid.kernel = KernelKind::CubicSpline;
  return scene;
}

void expectTheSameAfter(const Scene& scene, int steps) {
  Simulation cpu(scene, testing::on(Backend::Cpu));
  Simulation gpu(scene, testing::on(Backend::Cuda));
  ASSERT_STREQ(gpu.backendName(), "cuda");
  for (int i = 0; i < steps; ++i) {
    cpu.step();
    gpu.step();
  }
  const ParticleFrame a = cpu.frame(false), b = gpu.frame(false);
  ASSERT_EQ(a.id, b.id);
  const double h = cpu.calibration().supportRadius;
  double worstPosition = 0.0, worstDensity = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) d2 += std::pow(a.position[3 * i + k] - b.position[3 * i + k], 2);
    worstPosition = std::max(worstPosition, std::sqrt(d2));
    worstDensity = std::max(worstDensity, std::abs(double(a.density[i]) - b.density[i]) / 1000.0);
  }
  // Stated tolerance: every particle within 1 % of h, every density within 0.1 % of ρ0.
  EXPECT_LT(worstPosition, 0.01 * h);
  EXPECT_LT(worstDensity, 1e-3);
}

TEST(BackendEquivalence, DamBreakAfter200StepsMatchesTheCpu) {
  SPH_SKIP_UNLESS_AVAILABLE(Backend::Cuda);
  expectTheSameAfter(collapsingColumn(FluidSolver::Wcsph), 200);
}

// The incompressible solver's iterations stop on an error summed in fixed point, the same on
// both; its steps are about ten times longer, so 30 of them cover about as much time.
TEST(BackendEquivalence, DfsphDamBreakAfter30StepsMatchesTheCpu) {
  SPH_SKIP_UNLESS_AVAILABLE(Backend::Cuda);
  expectTheSameAfter(collapsingColumn(FluidSolver::Dfsph), 30);
}

}  // namespace
}  // namespace sph
