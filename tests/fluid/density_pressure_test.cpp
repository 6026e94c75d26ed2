// The density pass (density_pressure.hpp), both walks: each density the brute-force kernel sum
// over every particle within the support, and every neighbour within h listed, itself not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid_fixture.hpp"

namespace sph::fluid {
namespace {

using namespace testing;

class DensityStage : public ::testing::TestWithParam<NeighborWalk> {};

TEST_P(DensityStage, TheDensityPassSumsTheKernelOverEveryNeighbourWithinTheSupport) {
  const Lattice lattice = jitteredLattice(1.0f, 0.2f, 0.0f, 5);
  for (KernelKind kernel : {KernelKind::CubicSpline, KernelKind::Muller}) {
    Fluid fluid(lattice, kernel, ViscosityModel::Artificial);
    fluid.densityPass(GetParam());
    const std::vector<float> density = fluid.byId(fluid.particles.density);
    const std::vector<std::uint32_t> listed = fluid.byId(fluid.particles.neighborCount);
    const double h = fluid.params.h;
    for (std::size_t i = 0; i < lattice.position.size(); ++i) {
      const double expected = kernel == KernelKind::CubicSpline
                                  ? bruteForceDensity(CubicSplineKernels<double>::make(h),
                                                      lattice.position, i, fluid.params.mass)
                                  : bruteForceDensity(MullerKernels<double>::make(h),
                                                      lattice.position, i, fluid.params.mass);
      ASSERT_NEAR(density[i], expected, 2e-5 * expected) << "particle " << i;
      // Every neighbour within h listed, itself not.
      const BruteNeighbours brute = bruteForceNeighbours(lattice.position, i, h);
      ASSERT_GE(listed[i], brute.surely) << "particle " << i;
      ASSERT_LE(listed[i], brute.possibly) << "particle " << i;
    }
  }
}

SPH_BOTH_WALKS(DensityStage);

}  // namespace
}  // namespace sph::fluid
