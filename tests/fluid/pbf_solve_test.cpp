// The position solver (pbf_solve.hpp), both walks: its iterations undo a compression, every pair
// moving both its particles equally and oppositely (so the centre of mass stays and no momentum
// is made), the velocity is the move over the substep, and fluid that is not compressed is left
// where it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fluid_fixture.hpp"
#include "sph/core/kernels.hpp"

namespace sph::fluid {
namespace {

using namespace testing;

class PositionSolveStage : public ::testing::TestWithParam<NeighborWalk> {};

// Σ_j |V ∇W_ij|² on the rest lattice: the constraint gradient's sum that scales ε.
float latticeGradientSquares() {
  const auto kernels = CubicSplineKernels<double>::make(2.0 * kSpacing);
  const double volume = double(kSpacing) * kSpacing * kSpacing;
  double sum = 0.0;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j)
      for (int k = -2; k <= 2; ++k) {
        const double r = kSpacing * std::sqrt(double(i * i + j * j + k * k));
        const double g = volume * kernels.gradFactor(r) * r;
        sum += g * g;
      }
  return float(sum);
}

// As the scenes have it: ε the lattice's sum (fluid.pbf.relaxation 1), no tensile correction.
PbfSettings settingsWith(int iterations) {
  PbfSettings s;
  s.iterations = iterations;
  s.relaxation = latticeGradientSquares();
  s.tensileStrength = 0.0f;
  s.tensileDistance = 0.2f * 2.0f * kSpacing;
  return s;
}

struct Solved {
  float largest = 0.0f;  // the last iteration's largest compression
  double centre[3] = {0, 0, 0};
  std::vector<Vec3> position, velocity;  // by id
};

Solved solveLattice(const Lattice& lattice, const PbfSettings& settings, float dt,
                    NeighborWalk walk, std::size_t* clamped = nullptr) {
  Fluid fluid(lattice, KernelKind::CubicSpline, ViscosityModel::Artificial);
  fluid.params.pressureForces = false;
  fluid.densityPass(walk);
  const SolverReport report =
      solvePositions(fluid.particles, fluid.grid, fluid.walls, fluid.objects, fluid.params,
                     settings, dt, fluid.domain, walk);
  Solved s;
  s.largest = report.largestError;
  if (clamped != nullptr) *clamped = report.clamped;
  const std::vector<Vec4> x = fluid.byId(fluid.particles.position);
  const std::vector<Vec4> v = fluid.byId(fluid.particles.velocity);
  for (std::size_t i = 0; i < x.size(); ++i) {
    s.position.push_back(xyz(x[i]));
    s.velocity.push_back(xyz(v[i]));
    for (int a = 0; a < 3; ++a) s.centre[a] += double((&x[i].x)[a]) / double(x.size());
  }
  return s;
}

TEST_P(PositionSolveStage, IterationsUndoACompressionWithoutMovingTheCentreOfMass) {
  // 5 % closer than the rest lattice: about 16 % compressed inside.
  const Lattice lattice = jitteredLattice(0.95f, 0.05f, 0.0f, 31);
  double centre[3] = {0, 0, 0};
  for (const Vec3& x : lattice.position)
    for (int a = 0; a < 3; ++a) centre[a] += double((&x.x)[a]) / double(lattice.position.size());
  const float dt = 1e-3f;
  float previous = 1e30f;
  for (int iterations : {1, 2, 4, 8}) {
    const Solved s = solveLattice(lattice, settingsWith(iterations), dt, GetParam());
    // Each iteration's error is measured before its correction: more iterations, less left.
    EXPECT_LT(s.largest, previous) << iterations << " iterations";
    previous = s.largest;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(s.centre[a], centre[a], 1e-7) << "axis " << a;
    // The velocity is the move over the substep (the fluid started at rest).
    for (std::size_t i = 0; i < lattice.position.size(); ++i) {
      const Vec3 move = s.position[i] - lattice.position[i];
      ASSERT_NEAR(s.velocity[i].x, move.x / dt, 1e-3f + 1e-3f * std::abs(move.x / dt));
      ASSERT_NEAR(s.velocity[i].y, move.y / dt, 1e-3f + 1e-3f * std::abs(move.y / dt));
    }
  }
  EXPECT_GT(solveLattice(lattice, settingsWith(1), dt, GetParam()).largest, 0.1f);
  EXPECT_LT(previous, 0.03f);
}

TEST_P(PositionSolveStage, LeavesFluidThatIsNotCompressedWhereItIs) {
  const Lattice lattice = jitteredLattice(1.1f, 0.0f, 0.0f, 32);
  const Solved s = solveLattice(lattice, settingsWith(3), 1e-3f, GetParam());
  for (std::size_t i = 0; i < lattice.position.size(); ++i) {
    ASSERT_EQ(s.position[i].x, lattice.position[i].x) << "particle " << i;
    ASSERT_EQ(s.position[i].y, lattice.position[i].y) << "particle " << i;
    ASSERT_EQ(s.position[i].z, lattice.position[i].z) << "particle " << i;
  }
}

// The last guard: a speed past it is limited to it, in its direction, and counted.
TEST_P(PositionSolveStage, LimitsASpeedPastTheGuardAndCountsIt) {
  const Lattice lattice = jitteredLattice(0.95f, 0.05f, 0.0f, 31);
  const float dt = 1e-3f;
  const Solved free = solveLattice(lattice, settingsWith(2), dt, GetParam());
  float fastest = 0.0f;
  for (const Vec3& v : free.velocity) fastest = std::max(fastest, length(v));
  ASSERT_GT(fastest, 0.0f);
  PbfSettings guarded = settingsWith(2);
  guarded.maxSpeed = 0.5f * fastest;
  std::size_t clamped = 0;
  const Solved s = solveLattice(lattice, guarded, dt, GetParam(), &clamped);
  std::size_t expected = 0;
  for (std::size_t i = 0; i < s.velocity.size(); ++i) {
    const float before = length(free.velocity[i]);
    if (before <= guarded.maxSpeed) {
      ASSERT_EQ(s.velocity[i].x, free.velocity[i].x) << "particle " << i;
      continue;
    }
    ++expected;
    EXPECT_NEAR(length(s.velocity[i]), guarded.maxSpeed, 1e-5f * guarded.maxSpeed);
    EXPECT_NEAR(dot(s.velocity[i], free.velocity[i]), length(s.velocity[i]) * before,
                1e-4f * before * guarded.maxSpeed);
    // Where the constraints put it: the guard limits the speed, not the correction.
    EXPECT_EQ(s.position[i].x, free.position[i].x);
  }
  EXPECT_GT(expected, 0u);
  EXPECT_EQ(clamped, expected);
}

SPH_BOTH_WALKS(PositionSolveStage);

}  // namespace
}  // namespace sph::fluid
