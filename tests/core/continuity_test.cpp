#include "sph/core/continuity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sph/core/kernels.hpp"

namespace sph {
namespace {

const float kSpacing = 0.01f, kH = 0.02f, kRho0 = 1000.0f, kC0 = 20.0f;
const float kMass = kRho0 * kSpacing * kSpacing * kSpacing;
const auto kKernels = CubicSplineKernels<float>::make(kH);
const Vec3 kGravity{0.0f, -9.81f, 0.0f};
const float kCoefficient = 0.1f * kH * kC0;  // δ h c0

float diffusion(float rhoI, float rhoJ, Vec3 rij) {
  const Vec3 gradW = rij * kKernels.gradFactor(length(rij));
  return densityDiffusionTerm(kCoefficient, rhoI, rhoJ, kMass, rij, lengthSquared(rij), gradW,
                              kGravity, kRho0, kC0);
}

TEST(DensityDiffusion, FlowsFromTheDenserNeighbourToTheLighter) {
  const Vec3 rij{0.01f, 0.0f, 0.004f};  // side by side: no hydrostatic difference
  EXPECT_GT(diffusion(1000.0f, 1010.0f, rij), 0.0f);
  EXPECT_LT(diffusion(1010.0f, 1000.0f, rij), 0.0f);
  EXPECT_EQ(diffusion(1005.0f, 1005.0f, rij), 0.0f);
  // Antisymmetric over the pair: V_i dρ_i/dt = -V_j dρ_j/dt (equal masses, V = m/ρ).
  const float gainI = diffusion(1000.0f, 1010.0f, rij) / 1000.0f;
  const float lossJ = diffusion(1010.0f, 1000.0f, -rij) / 1010.0f;
  EXPECT_NEAR(gainI, -lossJ, 1e-6f * std::fabs(gainI));
}

TEST(DensityDiffusion, LeavesTheHydrostaticDensityAlone) {
  // j a spacing above i, lighter by the hydrostatic difference ρ0 g d / c0².
  const Vec3 rij{0.0f, -kSpacing, 0.0f};
  const float hydrostatic = kRho0 * 9.81f * kSpacing / (kC0 * kC0);
  // Within what float densities near 1000 resolve (6e-5 kg/m³) of a difference of 1 kg/m³.
  const float perUnit = diffusion(1000.0f, 1001.0f, Vec3{kSpacing, 0.0f, 0.0f});
  EXPECT_NEAR(diffusion(1000.0f + hydrostatic, 1000.0f, rij), 0.0f, 1e-4f * perUnit);
  EXPECT_GT(std::fabs(diffusion(1000.0f, 1000.0f, rij)), 0.5f * hydrostatic * perUnit);
  // Any other difference diffuses as it would sideways.
  const float extra = 2.0f;
  EXPECT_NEAR(diffusion(1000.0f + hydrostatic, 1000.0f + extra, rij),
              diffusion(1000.0f, 1000.0f + extra, Vec3{kSpacing, 0.0f, 0.0f}), 1e-4f * perUnit);
}

TEST(DensityDiffusion, ScalesWithTheCoefficientAndVanishesOutsideTheSupport) {
  const Vec3 rij{0.012f, 0.0f, 0.0f};
  const Vec3 gradW = rij * kKernels.gradFactor(length(rij));
  const float once = densityDiffusionTerm(kCoefficient, 1000.0f, 1010.0f, kMass, rij,
                                          lengthSquared(rij), gradW, kGravity, kRho0, kC0);
  const float twice = densityDiffusionTerm(2.0f * kCoefficient, 1000.0f, 1010.0f, kMass, rij,
                                           lengthSquared(rij), gradW, kGravity, kRho0, kC0);
  EXPECT_FLOAT_EQ(twice, 2.0f * once);
  const Vec3 far{0.03f, 0.0f, 0.0f};
  EXPECT_EQ(diffusion(1000.0f, 1010.0f, far), 0.0f);
}

}  // namespace
}  // namespace sph
