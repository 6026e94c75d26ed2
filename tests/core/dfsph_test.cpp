#include "sph/core/dfsph.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "sph/core/kernels.hpp"
#include "sph/core/momentum.hpp"

namespace sph {
namespace {

const float kSpacing = 0.01f, kH = 0.02f, kRho0 = 1000.0f;
const float kVolume = kSpacing * kSpacing * kSpacing, kMass = kRho0 * kVolume;
const auto kKernels = CubicSplineKernels<float>::make(kH);

Vec3 gradW(Vec3 rij) {
  return rij * kKernels.gradFactor(length(rij));
}

TEST(Dfsph, DensityRisesWhereParticlesApproach) {
  const Vec3 rij{0.01f, 0.002f, 0.0f};
  const Vec3 closing{-0.3f, 0.0f, 0.0f};  // i moves towards j
  EXPECT_GT(densityRateTerm(kMass, closing, gradW(rij)), 0.0f);
  EXPECT_LT(densityRateTerm(kMass, -closing, gradW(rij)), 0.0f);
  // Both particles of the pair see the same rate.
  EXPECT_FLOAT_EQ(densityRateTerm(kMass, closing, gradW(rij)),
                  densityRateTerm(kMass, -closing, gradW(-rij)));
}

// The factor is the solve's diagonal: K_i = e β / (ρ0 Δt²) applied by the velocity correction
// to i and its neighbours (whose own K is zero) changes i's predicted density by exactly -e ρ0.
TEST(Dfsph, TheFactorUndoesTheParticlesOwnErrorInOneCorrection) {
  // Particle i at the origin, with fluid on a lattice around it and a wall below.
  std::vector<Vec3> fluid, wall;
  for (int x = -2; x <= 2; ++x)
    for (int y = -1; y <= 2; ++y)
      for (int z = -2; z <= 2; ++z)
        if (x != 0 || y != 0 || z != 0)
          fluid.push_back(Vec3{x * kSpacing, y * kSpacing, z * kSpacing});
  for (int x = -2; x <= 2; ++x)
    for (int z = -2; z <= 2; ++z) wall.push_back(Vec3{x * kSpacing, -2 * kSpacing, z * kSpacing});
  Vec3 g{0, 0, 0}, gWall{0, 0, 0};
  float squares = 0.0f;
  for (Vec3 x : fluid) {
    const Vec3 v = gradW(-x) * kVolume;
    g += v;
    squares += dot(v, v);
  }
  for (Vec3 x : wall) {
    g += gradW(-x) * kVolume;
    gWall += gradW(-x) * kVolume;
  }
  const float beta = dfsphFactor(g, gWall, squares, dfsphSmallestFactorSum(kH));
  ASSERT_GT(beta, 0.0f);
  const float e = 0.003f, dt = 0.002f;
  const float k = dfsphStiffness(e, beta, kRho0, dt);
  // Δv of i, the wall mirroring K_i; Δv of each fluid neighbour j from K_i alone.
  Vec3 dvi{0, 0, 0};
  for (Vec3 x : fluid) dvi += pressureAccelerationSymmetric(kMass, k, 0.0f, gradW(-x)) * dt;
  for (Vec3 x : wall) dvi += pressureAccelerationSymmetric(kMass, k, k, gradW(-x)) * dt;
  float change = 0.0f;
  for (Vec3 x : fluid) {
    const Vec3 dvj = pressureAccelerationSymmetric(kMass, 0.0f, k, gradW(x)) * dt;
    change += dt * densityRateTerm(kMass, dvi - dvj, gradW(-x));
  }
  for (Vec3 x : wall) change += dt * densityRateTerm(kMass, dvi, gradW(-x));
  EXPECT_NEAR(change, -e * kRho0, 1e-3f * e * kRho0);
}

// A full neighbourhood sums to about 1.7/h²; the floor below which a particle is left alone is
// far under it.
TEST(Dfsph, AFullNeighbourhoodIsFarAboveTheFloor) {
  float squares = 0.0f;
  for (int x = -2; x <= 2; ++x)
    for (int y = -2; y <= 2; ++y)
      for (int z = -2; z <= 2; ++z) {
        const Vec3 v = gradW(Vec3{x * kSpacing, y * kSpacing, z * kSpacing}) * kVolume;
        squares += dot(v, v);
      }
  EXPECT_GT(squares * kH * kH, 1.0f);
  EXPECT_LT(squares * kH * kH, 3.0f);
  EXPECT_GT(squares, 100.0f * dfsphSmallestFactorSum(kH));
  EXPECT_EQ(dfsphFactor(Vec3{0, 0, 0}, Vec3{0, 0, 0}, 0.0f, dfsphSmallestFactorSum(kH)), 0.0f);
}

TEST(Dfsph, StiffnessScalesWithTheErrorAndInverselyWithTheStepSquared) {
  EXPECT_FLOAT_EQ(dfsphStiffness(0.002f, 1e-4f, kRho0, 0.001f),
                  2.0f * dfsphStiffness(0.001f, 1e-4f, kRho0, 0.001f));
  EXPECT_FLOAT_EQ(dfsphStiffness(0.001f, 1e-4f, kRho0, 0.001f),
                  4.0f * dfsphStiffness(0.001f, 1e-4f, kRho0, 0.002f));
}

}  // namespace
}  // namespace sph
