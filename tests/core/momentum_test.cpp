#include "sph/core/momentum.hpp"

#include <gtest/gtest.h>

#include "sph/core/kernels.hpp"

namespace sph {
namespace {

const auto kKernels = MullerKernels<float>::make(0.02);
const Vec3 kXi{0.001f, 0.002f, 0.0f}, kXj{0.009f, -0.003f, 0.004f};
const Vec3 kVi{0.3f, -0.1f, 0.2f}, kVj{-0.2f, 0.05f, 0.1f};

Vec3 gradW(Vec3 rij) {
  return rij * kKernels.gradFactor(length(rij));
}

void expectOpposite(Vec3 a, Vec3 b) {
  EXPECT_NEAR(a.x, -b.x, 1e-5f * std::abs(a.x) + 1e-9f);
  EXPECT_NEAR(a.y, -b.y, 1e-5f * std::abs(a.y) + 1e-9f);
  EXPECT_NEAR(a.z, -b.z, 1e-5f * std::abs(a.z) + 1e-9f);
}

// With equal masses, the acceleration i gets from j is minus what j gets from i.
TEST(Momentum, PressureFormsAreAntisymmetric) {
  const Vec3 rij = kXi - kXj;
  const float pi = 300.0f, pj = 120.0f, rhoi = 1003.0f, rhoj = 1001.0f, m = 0.008f;
  const float ti = pressureOverDensitySquared(pi, rhoi), tj = pressureOverDensitySquared(pj, rhoj);
  expectOpposite(pressureAccelerationSymmetric(m, ti, tj, gradW(rij)),
                 pressureAccelerationSymmetric(m, tj, ti, gradW(-rij)));
  expectOpposite(pressureAccelerationPaper(m, pi, 1.0f / rhoi, pj, 1.0f / rhoj, gradW(rij)),
                 pressureAccelerationPaper(m, pj, 1.0f / rhoj, pi, 1.0f / rhoi, gradW(-rij)));
  // The symmetric form is the 2021 CUDA SPH tutorial's p_i/ρ_i² + p_j/ρ_j²; the paper's is
  // (p_i+p_j)/(2ρ_iρ_j).
  const Vec3 g = gradW(rij);
  const Vec3 sym = pressureAccelerationSymmetric(m, ti, tj, g);
  EXPECT_NEAR(sym.x, -m * (pi / (rhoi * rhoi) + pj / (rhoj * rhoj)) * g.x, 1e-6f * std::abs(sym.x));
  const Vec3 paper = pressureAccelerationPaper(m, pi, 1.0f / rhoi, pj, 1.0f / rhoj, g);
  EXPECT_NEAR(paper.x, -m * (pi + pj) / (2 * rhoi * rhoj) * g.x, 1e-6f * std::abs(paper.x));
}

TEST(Momentum, PressureRepels) {
  const Vec3 rij = kXi - kXj;
  const Vec3 a =
      pressureAccelerationSymmetric(0.008f, pressureOverDensitySquared(300.0f, 1000.0f),
                                    pressureOverDensitySquared(300.0f, 1000.0f), gradW(rij));
  EXPECT_GT(dot(a, rij), 0.0f);  // pushes i away from j
}

TEST(Momentum, ViscositiesAreAntisymmetricAndDamp) {
  const Vec3 rij = kXi - kXj, vij = kVi - kVj;
  const float r = length(rij);
  const Vec3 m1 =
      mullerViscosityAcceleration(0.1f, 0.008f, 1000.0f, 1010.0f, vij, kKernels.laplacian(r));
  expectOpposite(
      m1, mullerViscosityAcceleration(0.1f, 0.008f, 1010.0f, 1000.0f, -vij, kKernels.laplacian(r)));
  EXPECT_LT(dot(m1, vij), 0.0f);  // reduces the relative velocity

  const Vec3 a1 = artificialViscosityAcceleration(0.1f, 20.0f, 0.02f, 0.008f, 1000.0f, 1010.0f, vij,
                                                  rij, r * r, gradW(rij));
  const Vec3 a2 = artificialViscosityAcceleration(0.1f, 20.0f, 0.02f, 0.008f, 1010.0f, 1000.0f,
                                                  -vij, -rij, r * r, gradW(-rij));
  ASSERT_LT(dot(vij, rij), 0.0f);  // the pair approaches
  expectOpposite(a1, a2);
  EXPECT_LT(dot(a1, vij), 0.0f);
  // Receding pairs feel nothing.
  const Vec3 none = artificialViscosityAcceleration(0.1f, 20.0f, 0.02f, 0.008f, 1000.0f, 1000.0f,
                                                    -vij, rij, r * r, gradW(rij));
  EXPECT_EQ(length(none), 0.0f);
}

TEST(Momentum, BoundaryPressurePushesAwayFromWall) {
  const Vec3 rib{0.0f, 0.008f, 0.0f};  // fluid above the wall particle
  const Vec3 a = boundaryPressureAcceleration(0.008f, 500.0f, 1000.0f, 500.0f, gradW(rib));
  EXPECT_GT(a.y, 0.0f);
  // A mirror particle at the same pressure pushes exactly as a fluid neighbour would.
  const Vec3 fluid =
      pressureAccelerationSymmetric(0.008f, pressureOverDensitySquared(500.0f, 1000.0f),
                                    pressureOverDensitySquared(500.0f, 1000.0f), gradW(rib));
  EXPECT_FLOAT_EQ(a.y, fluid.y);
}

TEST(Momentum, WallPressureGrowsWithDepth) {
  const Vec3 g{0.0f, -9.81f, 0.0f};
  // A wall particle 1 cm below the fluid particle sits under 1 cm more water.
  EXPECT_NEAR(wallPressure(200.0f, 1000.0f, g, Vec3{0.0f, -0.01f, 0.0f}, true), 298.1f, 1e-3f);
  EXPECT_NEAR(wallPressure(200.0f, 1000.0f, g, Vec3{0.01f, 0.0f, 0.0f}, true), 200.0f, 1e-4f);
  EXPECT_EQ(wallPressure(50.0f, 1000.0f, g, Vec3{0.0f, 0.01f, 0.0f}, true), 0.0f);
  EXPECT_LT(wallPressure(50.0f, 1000.0f, g, Vec3{0.0f, 0.01f, 0.0f}, false), 0.0f);
}

TEST(Momentum, SurfaceTensionPullsAlongTheNormalOnlyAtTheSurface) {
  // At the surface the colour gradient points into the fluid; a negative Laplacian (a convex
  // surface) pulls the particle inward, along it, by σ |∇²c| / ρ.
  const Vec3 inward{0.0f, -40.0f, 0.0f};
  const Vec3 a = surfaceTensionAcceleration(0.07f, 10.0f, inward, -2000.0f, 1000.0f);
  EXPECT_NEAR(a.y, -0.07f * 2000.0f / 1000.0f, 1e-6f);
  EXPECT_EQ(a.x, 0.0f);
  // Below the threshold the gradient is noise of the interior: no force.
  const Vec3 none =
      surfaceTensionAcceleration(0.07f, 10.0f, Vec3{0.0f, -9.0f, 0.0f}, -2000.0f, 1000.0f);
  EXPECT_EQ(length(none), 0.0f);
}

}  // namespace
}  // namespace sph
