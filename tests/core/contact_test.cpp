#include "sph/core/contact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sph {
namespace {

constexpr ContactCoefficients kCoefficients{200.0f, 0.5f, 0.25f};

TEST(DemContact, NoForceOutsideReach) {
  const Vec3 f =
      demContactForce(kCoefficients, Vec3{0.011f, 0, 0}, Vec3{1, 2, 3}, 0.01f, 1.0f, true);
  EXPECT_EQ(f.x, 0.0f);
  EXPECT_EQ(f.y, 0.0f);
  EXPECT_EQ(f.z, 0.0f);
}

TEST(DemContact, SpringPushesApartInProportionToOverlap) {
  // Meteer 2011, eq. 13: k (reach - |r|) along r̂, scaled by the distance function.
  const Vec3 f =
      demContactForce(kCoefficients, Vec3{0, 0.006f, 0}, Vec3{0, 0, 0}, 0.01f, 2.0f, true);
  EXPECT_NEAR(f.y, 200.0f * 2.0f * 0.004f, 1e-5f);
  EXPECT_EQ(f.x, 0.0f);
  EXPECT_EQ(f.z, 0.0f);
}

TEST(DemContact, DampingFollowsRelativeVelocityAndShearItsTangentialPart) {
  // Meteer 2011, eqs. 14-16 with r̂ = x: v = (1, 2, 0) → damping 0.5 v, shear 0.25 (0, 2, 0).
  const Vec3 f =
      demContactForce(kCoefficients, Vec3{0.01f, 0, 0}, Vec3{1, 2, 0}, 0.02f, 1.0f, true);
  EXPECT_NEAR(f.x, 200.0f * 0.01f + 0.5f * 1.0f, 1e-5f);
  EXPECT_NEAR(f.y, 0.5f * 2.0f + 0.25f * 2.0f, 1e-6f);
  EXPECT_NEAR(f.z, 0.0f, 1e-7f);
}

TEST(DemContact, CutParticlesAreNotDamped) {
  const Vec3 damped =
      demContactForce(kCoefficients, Vec3{0.01f, 0, 0}, Vec3{1, 2, 0}, 0.02f, 1.0f, true);
  const Vec3 cut =
      demContactForce(kCoefficients, Vec3{0.01f, 0, 0}, Vec3{1, 2, 0}, 0.02f, 1.0f, false);
  EXPECT_NEAR(damped.x - cut.x, 0.5f, 1e-6f);
  EXPECT_NEAR(damped.y - cut.y, 1.0f, 1e-6f);
  EXPECT_NEAR(cut.y, 0.5f, 1e-6f);  // the shear term stays
}

TEST(DemContact, ThePairForcesAreExactNegations) {
  // The contact pass evaluates a pair once from each side with the same arguments; Newton's
  // third law then holds to the bit.
  const Vec3 offset{0.0031f, -0.0047f, 0.0012f};
  const Vec3 relative{0.3f, -0.7f, 1.1f};
  const Vec3 onA = demContactForce(kCoefficients, offset, relative, 0.008f, 3.7f, true);
  const Vec3 onB = -demContactForce(kCoefficients, offset, relative, 0.008f, 3.7f, true);
  EXPECT_EQ(onA.x + onB.x, 0.0f);
  EXPECT_EQ(onA.y + onB.y, 0.0f);
  EXPECT_EQ(onA.z + onB.z, 0.0f);
}

TEST(SpringTension, HookePlusDashpotAlongTheSpring) {
  // Stretched 2 mm at 50 N/m and opening at 0.1 m/s against 0.3 N·s/m: 0.1 + 0.03 N.
  EXPECT_NEAR(springTension(50.0, 0.3, 0.012, 0.010, 0.1), 0.13, 1e-12);
  // Compressed and closing: it pushes the ends apart.
  EXPECT_NEAR(springTension(50.0, 0.3, 0.009, 0.010, -0.1), -0.08, 1e-12);
  EXPECT_EQ(springTension(50.0f, 0.0f, 0.01f, 0.01f, 0.0f), 0.0f);
}

TEST(DistanceFunction, TableFollowsTheExponentialAndRisesInward) {
  for (double beta : {0.0, 2.0, 4.0, 6.0}) {
    const DistanceFunctionTable table = DistanceFunctionTable::make(beta);
    EXPECT_FLOAT_EQ(table(1.0f), 1.0f);
    EXPECT_NEAR(table(0.0f), std::exp(beta), 1e-4 * std::exp(beta));
    // The peak the calibration and the step bound use is the table's largest value.
    EXPECT_EQ(distanceFunctionPeak(beta), std::exp(beta));
    EXPECT_NEAR(table(0.0f), distanceFunctionPeak(beta), 1e-4 * distanceFunctionPeak(beta));
    float previous = table(1.0f);
    for (int k = 999; k >= 0; --k) {
      const float q = float(k) / 1000.0f;
      const float value = table(q);
      // Linear interpolation of a convex function lies above it by at most h²/8 f''.
      const double exact = distanceFunction(beta, q);
      const double h = 1.0 / DistanceFunctionTable::kSize;
      EXPECT_NEAR(value, exact, h * h / 8.0 * beta * beta * exact + 1e-5 * exact) << q;
      EXPECT_GE(value, previous);
      previous = value;
    }
    EXPECT_EQ(table(-0.5f), table(0.0f));
    EXPECT_EQ(table(1.5f), 1.0f);
  }
}

}  // namespace
}  // namespace sph
