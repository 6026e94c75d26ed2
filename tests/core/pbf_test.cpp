// Position Based Fluids' terms (core/pbf.hpp): the multiplier acts only against compression and
// in proportion to it, a pair's displacement terms are equal and opposite (so a solve moves no
// centre of mass), the tensile correction repels and vanishes at the support's edge, and the
// pressure the multipliers stand for holds a column's weight.
#include "sph/core/pbf.hpp"

#include <gtest/gtest.h>

#include "sph/core/kernels.hpp"

namespace sph {
namespace {

const float kH = 0.02f, kRho0 = 1000.0f, kVolume = 1e-6f;
const auto kKernels = CubicSplineKernels<float>::make(kH);

Vec3 gradW(Vec3 rij) {
  return rij * kKernels.gradFactor(length(rij));
}

TEST(Pbf, TheMultiplierActsOnlyAgainstCompressionAndInProportionToIt) {
  const float sum = 4000.0f, eps = 400.0f;
  EXPECT_EQ(pbfMultiplier(kRho0, kRho0, sum, eps), 0.0f);
  EXPECT_EQ(pbfMultiplier(0.9f * kRho0, kRho0, sum, eps), 0.0f);
  const float one = pbfMultiplier(1.01f * kRho0, kRho0, sum, eps);
  EXPECT_LT(one, 0.0f);
  EXPECT_NEAR(pbfMultiplier(1.02f * kRho0, kRho0, sum, eps), 2.0f * one, 1e-3f * std::abs(one));
  EXPECT_NEAR(one, -0.01f / (sum + eps), 1e-4f * std::abs(one));
}

TEST(Pbf, APairsDisplacementsAreEqualAndOppositeAndPushApartUnderCompression) {
  const Vec3 rij{0.008f, 0.003f, -0.002f};
  const float li = -2e-6f, lj = -5e-6f, tensile = -1e-7f;
  const Vec3 onI = pbfDisplacementTerm(kVolume, li, lj, tensile, gradW(rij));
  const Vec3 onJ = pbfDisplacementTerm(kVolume, lj, li, tensile, gradW(-rij));
  EXPECT_NEAR(onI.x, -onJ.x, 1e-12f);
  EXPECT_NEAR(onI.y, -onJ.y, 1e-12f);
  EXPECT_NEAR(onI.z, -onJ.z, 1e-12f);
  EXPECT_GT(dot(onI, rij), 0.0f) << "i moves away from j";
}

TEST(Pbf, TheTensileCorrectionRepelsAndVanishesAtTheSupportsEdge) {
  const float k = 1e-5f;
  EXPECT_FLOAT_EQ(pbfTensileCorrection(k, 1.0f), -k);
  EXPECT_FLOAT_EQ(pbfTensileCorrection(k, 0.5f), -k / 16.0f);
  EXPECT_EQ(pbfTensileCorrection(k, kKernels.W(kH * kH)), 0.0f);
}

TEST(Pbf, TheWallsMirrorTheMultiplier) {
  const Vec3 gw{0.0f, -300.0f, 0.0f};  // walls below
  const Vec3 dx = pbfWallDisplacement(-1e-6f, gw);
  EXPECT_GT(dx.y, 0.0f) << "a compressed particle moves off the wall";
  EXPECT_FLOAT_EQ(dx.y, 2.0f * 1e-6f * 300.0f);
}

// A column at rest: each substep the constraints take back what gravity moved, g Δt², so the
// multipliers summed over a substep grow with depth as -g Δt² depth, and stand for ρ0 g depth.
TEST(Pbf, TheMultipliersOfAColumnAtRestStandForItsWeight) {
  const float g = 9.81f, depth = 0.15f;
  for (float dt : {1e-4f, 1e-3f}) {
    const float sum = -g * dt * dt * depth;
    EXPECT_NEAR(pbfPressure(sum, kRho0, dt), kRho0 * g * depth, 1e-3f * kRho0 * g * depth);
  }
}

TEST(Pbf, XsphMovesAVelocityTowardsItsNeighbours) {
  const Vec3 vji{1.0f, 0.0f, 0.0f};
  const float volume = 1e-3f / kRho0, w = kKernels.W(0.0001f);
  const Vec3 dv = xsphTerm(0.01f, volume, vji, w);
  EXPECT_GT(dv.x, 0.0f);
  EXPECT_EQ(dv.y, 0.0f);
  // The pair's other particle takes the opposite: m Δv_i + m Δv_j = 0.
  const Vec3 back = xsphTerm(0.01f, volume, Vec3{-1.0f, 0.0f, 0.0f}, w);
  EXPECT_EQ(dv.x + back.x, 0.0f);
}

}  // namespace
}  // namespace sph
