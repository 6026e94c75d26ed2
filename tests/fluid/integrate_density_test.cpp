// The continuity pass (integrate_density.hpp), both walks: Dρ/Dt = -ρ ∇·v in the bulk, zero
// for a fluid that moves as one, and the pressure follows the new density.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fluid_fixture.hpp"

namespace sph::fluid {
namespace {

using namespace testing;

class ContinuityStage : public ::testing::TestWithParam<NeighborWalk> {};

// Particles at least three spacings inside each face of the 10 × 10 × 10 lattice.
bool inner(std::size_t i) {
  const int a = int(i / 100), b = int(i / 10 % 10), c = int(i % 10);
  return std::min({a, b, c}) >= 3 && std::max({a, b, c}) <= 6;
}

// The lattice's densities kept as state (as the engine keeps them with continuity), then one
// continuity step over dt with δ-SPH's diffusion δ.
std::vector<float> advanced(Fluid& fluid, NeighborWalk walk, float dt, float diffusion) {
  fluid.params.continuityDensity = true;
  fluid.params.densityDiffusion = diffusion;
  fluid.densityPass(walk);
  fluid.particles.densityIsState = true;
  integrateDensity(fluid.particles, fluid.grid, fluid.walls, fluid.params, dt, walk);
  return fluid.byId(fluid.particles.density);
}

// Without diffusion (which smooths the free surface's deficit), the density stays everywhere.
TEST_P(ContinuityStage, AFluidMovingAsOneKeepsItsDensity) {
  Lattice lattice = jitteredLattice(1.0f, 0.0f, 0.0f, 1);
  for (Vec3& v : lattice.velocity) v = Vec3{0.7f, -0.2f, 0.4f};
  Fluid fluid(lattice, KernelKind::CubicSpline, ViscosityModel::Artificial);
  fluid.densityPass(GetParam());
  const std::vector<float> before = fluid.byId(fluid.particles.density);
  const std::vector<float> after = advanced(fluid, GetParam(), 1e-3f, 0.0f);
  for (std::size_t i = 0; i < before.size(); ++i)
    ASSERT_NEAR(after[i], before[i], 1e-4f * before[i]) << "particle " << i;
}

// v = -α x: ∇·v = -3α, so the bulk's density rises at 3 α ρ. Pressure follows it.
TEST_P(ContinuityStage, AUniformCompressionRaisesTheDensityAtThreeAlphaRho) {
  const float alpha = 2.0f, dt = 1e-4f;
  Lattice lattice = jitteredLattice(1.0f, 0.0f, 0.0f, 1);
  for (std::size_t i = 0; i < lattice.position.size(); ++i)
    lattice.velocity[i] = lattice.position[i] * -alpha;
  Fluid fluid(lattice, KernelKind::CubicSpline, ViscosityModel::Artificial);
  fluid.densityPass(GetParam());
  const std::vector<float> before = fluid.byId(fluid.particles.density);
  const std::vector<float> after = advanced(fluid, GetParam(), dt, 0.1f);
  const std::vector<float> pressure = fluid.byId(fluid.particles.pressure);
  int checked = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (!inner(i)) continue;
    const double rate = (double(after[i]) - before[i]) / dt;
    EXPECT_NEAR(rate, 3.0 * alpha * before[i], 0.03 * 3.0 * alpha * before[i]) << "particle " << i;
    EXPECT_NEAR(pressure[i], fluid.params.stiffness * (after[i] - kRestDensity),
                1e-3f * fluid.params.stiffness * kRestDensity)
        << "particle " << i;
    ++checked;
  }
  EXPECT_EQ(checked, 64);
}

SPH_BOTH_WALKS(ContinuityStage);

}  // namespace
}  // namespace sph::fluid
