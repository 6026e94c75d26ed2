// The same scene on the CPU and on the GPU, for each fluid solver: after a dam break's first
// steps the positions and densities agree within a stated tolerance (float sums in another
// order, not another method).
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

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

// The incompressible solver makes two decisions on values that float rounding can tip: when
// a solve stops (its average error against the tolerance) and where the density solve starts
// warm (ρ_i ≥ ρ0). One iteration more on one backend, or one particle warm-started on one of
// them, and from there the runs part like two runs of a splash. Measured on an H200 after 30
// steps of this column: with both decisions fixed (4 iterations a solve, no warm start), the
// worst particle 0.024 % of h apart and 0.004 % of ρ0; with the warm start, 4 % of h from the
// 15th step on; with the shipped settings, 23 % of h, the first iteration count differing at
// the 3rd step. So the passes are compared with the decisions fixed, and the shipped settings by
// what the run does as a whole.
TEST(BackendEquivalence, DfsphPassesAfter30StepsMatchTheCpu) {
  SPH_SKIP_UNLESS_AVAILABLE(Backend::Cuda);
  Scene scene = collapsingColumn(FluidSolver::Dfsph);
  scene.fluid.dfsph.minIterations = scene.fluid.dfsph.maxIterations = 4;
  scene.fluid.dfsph.warmStart = false;
  expectTheSameAfter(scene, 30);
}

// Measured on an H200 after 30 steps (0.103 s): kinetic energy 0.09 % apart, mean density
// 0.0025 %, the same time reached.
TEST(BackendEquivalence, DfsphAsShippedCollapsesTheSameWayAsOnTheCpu) {
  SPH_SKIP_UNLESS_AVAILABLE(Backend::Cuda);
  const Scene scene = collapsingColumn(FluidSolver::Dfsph);
  Simulation cpu(scene, testing::on(Backend::Cpu));
  Simulation gpu(scene, testing::on(Backend::Cuda));
  for (int i = 0; i < 30; ++i) {
    cpu.step();
    gpu.step();
  }
  const auto wholeRun = [](const ParticleFrame& frame) {
    double kinetic = 0.0, density = 0.0;
    for (std::size_t i = 0; i < frame.size(); ++i) {
      for (int k = 0; k < 3; ++k) kinetic += std::pow(frame.velocity[3 * i + k], 2);
      density += frame.density[i];
    }
    return std::pair{kinetic, density / double(frame.size())};
  };
  const auto [cpuKinetic, cpuDensity] = wholeRun(cpu.frame(false));
  const auto [gpuKinetic, gpuDensity] = wholeRun(gpu.frame(false));
  EXPECT_NEAR(gpu.time(), cpu.time(), 1e-3 * cpu.time());
  EXPECT_NEAR(gpuKinetic, cpuKinetic, 0.01 * cpuKinetic);  // the column is falling: > 0
  EXPECT_NEAR(gpuDensity, cpuDensity, 5e-4 * cpuDensity);
  EXPECT_GT(cpuKinetic, 0.0);
}

// The position solver decides nothing on a tolerance: its iterations are fixed, and only the
// one-sided constraint (is a particle compressed?) can be tipped by rounding. Not yet measured
// on a GPU; the tolerance is the weakly compressible solver's.
TEST(BackendEquivalence, PbfAfter60SubstepsMatchesTheCpu) {
  SPH_SKIP_UNLESS_AVAILABLE(Backend::Cuda);
  expectTheSameAfter(collapsingColumn(FluidSolver::Pbf), 60);
}

}  // namespace
}  // namespace sph
