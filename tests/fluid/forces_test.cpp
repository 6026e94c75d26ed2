// The force pass (forces.hpp), both walks: every pair pushes and rubs both ways, so the
// accelerations of equal masses sum to nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid_fixture.hpp"

namespace sph::fluid {
namespace {

using namespace testing;

class ForceStage : public ::testing::TestWithParam<NeighborWalk> {};

TEST_P(ForceStage, TheForcePassesPairTermsCancelAcrossTheFluid) {
  // Compressed by 3 %, moving at up to 0.5 m/s in every direction: every pair pushes and rubs.
  const Lattice lattice = jitteredLattice(0.97f, 0.2f, 0.5f, 9);
  for (ViscosityModel viscosity : {ViscosityModel::Artificial, ViscosityModel::Muller}) {
    Fluid fluid(lattice, KernelKind::CubicSpline, viscosity);
    fluid.densityPass(GetParam());
    computeForces(fluid.particles, fluid.grid, fluid.walls, fluid.objects, fluid.params,
                  GetParam());
    const Imbalance imbalance = accelerationImbalance(fluid.particles);
    ASSERT_GT(imbalance.magnitude, 1.0);
    for (double share : imbalance.axis) EXPECT_LT(share, 1e-6);  // float rounding
  }
}

SPH_BOTH_WALKS(ForceStage);

}  // namespace
}  // namespace sph::fluid
