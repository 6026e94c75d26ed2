#include "sph/core/probe.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "sph/core/kernels.hpp"

namespace sph {
namespace {

// A lattice of spacing d filling space around the origin, with a pressure p(x) and a velocity:
// the probe's sums at `at`.
template <class PressureAt>
PointSums latticeSums(Vec3 at, double d, PressureAt pressureAt) {
  const auto kernels = CubicSplineKernels<float>::make(2.0 * d);
  const float volume = float(d * d * d);  // m/ρ at rest
  PointSums sums;
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j)
      for (int k = -6; k <= 6; ++k) {
        const Vec3 x{float((i + 0.5) * d), float((j + 0.5) * d), float((k + 0.5) * d)};
        const Vec3 r = at - x;
        addToPointSums(sums, volume * kernels.W(lengthSquared(r)), pressureAt(x), 1000.0f,
                       Vec3{0.1f, -0.2f, 0.3f});
      }
  return sums;
}

TEST(Probe, InsideTheFluidTheSupportIsFilledAndAConstantIsReadExactly) {
  const double d = 0.01;
  const Vec3 at{0.0013f, -0.0021f, 0.0007f};
  const PointSums sums = latticeSums(at, d, [](Vec3) { return 500.0f; });
  EXPECT_NEAR(sums.filled, 1.0, 0.02);  // a lattice's kernel sum, within its quadrature error
  const PointValues v = pointValues(sums);
  ASSERT_TRUE(v.wet);
  EXPECT_NEAR(v.pressure, 500.0, 1e-3);
  EXPECT_NEAR(v.density, 1000.0, 1e-3);
  EXPECT_NEAR(v.velocity.x, 0.1, 1e-6);
  EXPECT_NEAR(v.velocity.y, -0.2, 1e-6);
  EXPECT_NEAR(v.velocity.z, 0.3, 1e-6);
}

TEST(Probe, ALinearPressureIsReadAtThePoint) {
  // Hydrostatic: p = ρ g (H - y). A symmetric kernel averages a linear field to its value at
  // the centre, up to the lattice's quadrature error.
  const double d = 0.01;
  const Vec3 at{0.002f, 0.004f, -0.003f};
  const auto hydrostatic = [](Vec3 x) { return 1000.0f * 9.81f * (0.5f - x.y); };
  const PointValues v = pointValues(latticeSums(at, d, hydrostatic));
  EXPECT_NEAR(v.pressure, hydrostatic(at), 0.005 * hydrostatic(at));
}

TEST(Probe, APointInTheAirReadsNothing) {
  PointSums sums;
  addToPointSums(sums, 0.05f, 100.0f, 1000.0f, Vec3{1, 0, 0});
  EXPECT_FALSE(pointValues(sums).wet);
  addToPointSums(sums, 0.05f, 100.0f, 1000.0f, Vec3{1, 0, 0});
  EXPECT_TRUE(pointValues(sums).wet);  // at kSmallestFilledShare
}

TEST(Probe, TheLevelIsWhereTheFilledShareFallsThroughAHalf) {
  // Full up to 0.3, empty above 0.5, linear in between: 1/2 at 0.4.
  const float step = 0.05f;
  std::vector<float> filled;
  for (int k = 0; k <= 20; ++k) {
    const float s = k * step;
    filled.push_back(s <= 0.3f ? 1.0f : (s >= 0.5f ? 0.0f : (0.5f - s) / 0.2f));
  }
  EXPECT_NEAR(levelAlong(filled.data(), int(filled.size()), step), 0.4f, 1e-5);
  // A drop and a splash above the surface: the last crossing going up counts.
  filled[15] = 0.8f;
  EXPECT_NEAR(levelAlong(filled.data(), int(filled.size()), step), 0.76875f, 1e-5);
  // Dry, and full to the top.
  const std::vector<float> dry(5, 0.2f), full(5, 0.9f);
  EXPECT_EQ(levelAlong(dry.data(), 5, step), 0.0f);
  EXPECT_NEAR(levelAlong(full.data(), 5, step), 0.2f, 1e-6);
}

}  // namespace
}  // namespace sph
