// The CPU's batched passes (neighbours a SIMD batch at a time) against the one-at-a-time passes
// the GPU runs: after a few steps of a splashing tank, the same densities and velocities to
// float rounding, for every kernel, pressure form and viscosity, with surface tension.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

ParticleFrame runFor(const Scene& scene, const SimulationOptions& options, int steps) {
  Simulation sim(scene, options);
  for (int k = 0; k < steps; ++k) sim.step();
  return sim.frame(false);
}

SimulationOptions passes(CpuPasses walk, std::uint32_t listLength = 0) {
  SimulationOptions options;
  options.cpuPasses = walk;
  options.neighborListLength = listLength;
  return options;
}

void expectSameState(const Scene& scene, const SimulationOptions& a, const SimulationOptions& b,
                     const char* what) {
  const ParticleFrame one = runFor(scene, a, 5), batched = runFor(scene, b, 5);
  ASSERT_EQ(one.size(), batched.size()) << what;
  double density = 0.0, speed = 0.0;
  for (std::size_t i = 0; i < one.size(); ++i) {
    density = std::max(
        density, std::abs(double(one.density[i]) - batched.density[i]) / double(one.density[i]));
    for (int a = 0; a < 3; ++a)
      speed =
          std::max(speed, std::abs(double(one.velocity[3 * i + a]) - batched.velocity[3 * i + a]));
  }
  // Rounding: the batched pass sums in another order (measured 5e-7 and 4e-6 m/s).
  EXPECT_LT(density, 1e-5) << what;
  EXPECT_LT(speed, 1e-4) << what;
}

TEST(BatchedPasses, MatchTheOneAtATimePassesForEveryOption) {
  // A block falling into a tank: walls, a free surface and moving fluid.
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.fluid.blocks[0].box.max[1] = 0.06;
  scene.fluid.blocks[0].velocity = {0.3, -0.5, 0.2};
  scene.fluid.surfaceTension = 0.07;
  for (KernelKind kernel : {KernelKind::Muller, KernelKind::CubicSpline, KernelKind::WendlandC2})
    for (PressureForm form : {PressureForm::Symmetric, PressureForm::Paper})
      for (ViscosityModel viscosity : {ViscosityModel::Artificial, ViscosityModel::Muller}) {
        scene.fluid.kernel = kernel;
        scene.fluid.pressureForm = form;
        scene.fluid.viscosityModel = viscosity;
        expectSameState(scene, passes(CpuPasses::OneAtATime), passes(CpuPasses::Batched),
                        (std::to_string(int(kernel)) + "/" + std::to_string(int(form)) + "/" +
                         std::to_string(int(viscosity)))
                            .c_str());
      }
}

// Continuity density with δ-SPH: its pass, batched and one at a time, through lists and cells.
TEST(BatchedPasses, ContinuityDensityMatchesTheOneAtATimePass) {
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.fluid.blocks[0].box.max[1] = 0.06;
  scene.fluid.blocks[0].velocity = {0.3, -0.5, 0.2};
  scene.fluid.kernel = KernelKind::CubicSpline;
  scene.fluid.density = DensityModel::Continuity;
  expectSameState(scene, passes(CpuPasses::OneAtATime), passes(CpuPasses::Batched), "lists");
  expectSameState(scene, passes(CpuPasses::OneAtATime, 8), passes(CpuPasses::Batched, 8), "cells");
}

// A particle with more neighbours than its list holds finds them in the grid's cells: with
// lists of 24 most particles of a splashing tank take that path and some do not. Both walks
// must still give what lists long enough give.
TEST(BatchedPasses, ParticlesWithTooManyNeighboursToListSearchTheCells) {
  Scene scene = testing::restingTank(0.01, 0.1, 0.1);
  scene.fluid.blocks[0].box.max[1] = 0.06;
  scene.fluid.blocks[0].velocity = {0.3, -0.5, 0.2};
  scene.fluid.surfaceTension = 0.07;
  for (CpuPasses walk : {CpuPasses::OneAtATime, CpuPasses::Batched}) {
    const char* what = walk == CpuPasses::Batched ? "batched" : "one at a time";
    expectSameState(scene, passes(walk), passes(walk, 24), what);
    expectSameState(scene, passes(walk), passes(walk, 8), what);
  }
}

}  // namespace
}  // namespace sph
