// Lattice sampling (src/sim/sampling.cpp): a block is one particle at the centre of each cubic
// cell of the fluid spacing, so that every particle stands for the same volume d³; a tank's
// wall layers continue that lattice outside the inner faces, open where gravity would spill
// nothing. A hydrostatic block is squeezed so that each column keeps its mass: where the
// density is ρ0 (1 + g z / c0²) a layer of thickness d shrinks to d / (1 + g z / c0²), whose
// integral over the depth is z' = (c0²/g) ln(1 + g z / c0²).
#include "sim/sampling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace sph {
namespace {

constexpr double kSpacing = 0.01;

// The lattice cell a point is the centre of, found by rounding: a point off the centre by more
// than `tolerance` (in spacings) fails the test that calls it.
std::array<int, 3> cellOf(const Vec3& p, const Vec3d& origin, double d, double tolerance = 1e-3) {
  std::array<int, 3> cell{};
  const double x[3] = {p.x, p.y, p.z};
  for (int a = 0; a < 3; ++a) {
    const double index = (x[a] - origin[a]) / d - 0.5;
    cell[a] = int(std::lround(index));
    EXPECT_NEAR(index, cell[a], tolerance) << "axis " << a;
  }
  return cell;
}

TEST(Sampling, ABlockHasOneParticleAtTheCentreOfEachCell) {
  // 5 × 3 × 4 cells; the last extent is not a whole number of spacings and rounds to 4.
  const AxisBox box{{0.1, -0.2, 0.3}, {0.15, -0.17, 0.3405}};
  const std::vector<Vec3> points = sim::sampleBlock(box, kSpacing);
  ASSERT_EQ(points.size(), 5u * 3u * 4u);
  std::set<std::array<int, 3>> cells;
  for (const Vec3& p : points) {
    const std::array<int, 3> c = cellOf(p, box.min, kSpacing);
    EXPECT_TRUE(c[0] >= 0 && c[0] < 5 && c[1] >= 0 && c[1] < 3 && c[2] >= 0 && c[2] < 4);
    const double x[3] = {p.x, p.y, p.z};
    for (int a = 0; a < 3; ++a) {
      EXPECT_GT(x[a], box.min[a]);
      EXPECT_LT(x[a], box.max[a]);
    }
    cells.insert(c);
  }
  EXPECT_EQ(cells.size(), points.size());  // no cell twice: all 60 filled
}

TEST(Sampling, ABlockThinnerThanHalfASpacingHasNoParticles) {
  EXPECT_TRUE(sim::sampleBlock({{0, 0, 0}, {0.1, 0.004, 0.1}}, kSpacing).empty());
  EXPECT_TRUE(sim::sampleBlock({{0, 0, 0}, {0.1, 0.0, 0.1}}, kSpacing).empty());
}

// What a tank sampled with `layers` layers must look like: on the lattice of the inner box,
// outside it, within `layers` cells of it, and nothing on the open side.
struct TankCells {
  std::set<std::array<int, 3>> cells;
  std::size_t points = 0;
};

TankCells tankCells(const AxisBox& inner, int layers, bool closed, const Vec3d& gravity,
                    const int n[3], int openAxis, bool openAbove) {
  const std::vector<Vec3> points = sim::sampleTank(inner, layers, closed, kSpacing, gravity);
  TankCells out;
  out.points = points.size();
  for (const Vec3& p : points) {
    const std::array<int, 3> c = cellOf(p, inner.min, kSpacing);
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(c[a], -layers);
      EXPECT_LT(c[a], n[a] + layers);
      inside = inside && c[a] >= 0 && c[a] < n[a];
    }
    EXPECT_FALSE(inside) << "a wall particle in the fluid's cells";
    if (!closed) {
      if (openAbove) {
        EXPECT_LT(c[openAxis], n[openAxis]) << "a particle above the rim of an open tank";
      } else {
        EXPECT_GE(c[openAxis], 0) << "a particle below the rim of an open tank";
      }
    }
    out.cells.insert(c);
  }
  EXPECT_EQ(out.cells.size(), points.size());
  return out;
}

TEST(Sampling, ATankSurroundsItsInnerFacesWithItsLayers) {
  const AxisBox inner{{0, 0, 0}, {0.04, 0.03, 0.05}};
  const int n[3] = {4, 3, 5}, layers = 2;
  const Vec3d down{0, -9.81, 0};
  // Closed: the box grown by the layers on every side, less the inner box.
  const TankCells closed = tankCells(inner, layers, true, down, n, 1, true);
  EXPECT_EQ(closed.points, std::size_t((4 + 4) * (3 + 4) * (5 + 4) - 4 * 3 * 5));
  // Open: no layers above the rim, so grown by them below and sideways only.
  const TankCells open = tankCells(inner, layers, false, down, n, 1, true);
  EXPECT_EQ(open.points, std::size_t((4 + 4) * (3 + 2) * (5 + 4) - 4 * 3 * 5));
  for (const auto& c : open.cells) EXPECT_EQ(closed.cells.count(c), 1u);
}

TEST(Sampling, ATankIsOpenOnTheSideGravityPointsAwayFrom) {
  const AxisBox inner{{0, 0, 0}, {0.04, 0.03, 0.05}};
  const int n[3] = {4, 3, 5}, layers = 1;
  // Gravity along +y: "up" is -y, the open side below.
  const TankCells flipped = tankCells(inner, layers, false, {0, 9.81, 0}, n, 1, false);
  EXPECT_EQ(flipped.points, std::size_t((4 + 2) * (3 + 1) * (5 + 2) - 4 * 3 * 5));
  // Gravity mostly along -z: open above the largest z.
  const TankCells alongZ = tankCells(inner, layers, false, {1.0, 2.0, -9.81}, n, 2, true);
  EXPECT_EQ(alongZ.points, std::size_t((4 + 2) * (3 + 2) * (5 + 1) - 4 * 3 * 5));
  // No gravity: y is up.
  const TankCells weightless = tankCells(inner, layers, false, {0, 0, 0}, n, 1, true);
  EXPECT_EQ(weightless.points, std::size_t((4 + 2) * (3 + 1) * (5 + 2) - 4 * 3 * 5));
}

// A column of depth 0.1 m with a slow sound speed, so that the compression (4 %) is far above
// the positions' float rounding.
constexpr double kSoundSpeed = 5.0;
constexpr double kG = 9.81;

double compressedDepth(double depth) {
  const double c2 = kSoundSpeed * kSoundSpeed;
  return c2 / kG * std::log(1.0 + kG * depth / c2);
}

TEST(Sampling, HydrostaticCompressionMapsEachDepthLogarithmically) {
  const AxisBox block{{0.0, 0.02, -0.01}, {0.03, 0.12, 0.02}};
  const std::vector<Vec3> lattice = sim::sampleBlock(block, kSpacing);
  std::vector<Vec3> points = lattice;
  sim::compressHydrostatically(points, block, {0, -kG, 0}, kSoundSpeed);
  ASSERT_EQ(points.size(), lattice.size());
  double largestShift = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i].x, lattice[i].x);
    EXPECT_EQ(points[i].z, lattice[i].z);
    const double depth = block.max[1] - lattice[i].y;
    EXPECT_NEAR(block.max[1] - points[i].y, compressedDepth(depth), 1e-6);
    largestShift = std::max(largestShift, double(points[i].y - lattice[i].y));
  }
  // The deepest layer (0.095 m) sinks by about g z² / (2 c0²): 1.8 mm.
  EXPECT_GT(largestShift, 1e-3);
}

TEST(Sampling, HydrostaticCompressionMeasuresDepthFromTheTopAlongGravity) {
  // Gravity along +x: the top is the block's smallest x, and depth grows with x.
  const AxisBox block{{0.1, 0.0, 0.0}, {0.2, 0.02, 0.03}};
  const std::vector<Vec3> lattice = sim::sampleBlock(block, kSpacing);
  std::vector<Vec3> points = lattice;
  sim::compressHydrostatically(points, block, {kG, 0.5, 0}, kSoundSpeed);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i].y, lattice[i].y);
    EXPECT_EQ(points[i].z, lattice[i].z);
    EXPECT_NEAR(points[i].x - block.min[0], compressedDepth(lattice[i].x - block.min[0]), 1e-6);
  }
  // Without gravity, or without a sound speed, nothing is compressed.
  for (const auto& [gravity, c0] : {std::pair<Vec3d, double>{{0, 0, 0}, kSoundSpeed},
                                    std::pair<Vec3d, double>{{0, -kG, 0}, 0.0}}) {
    std::vector<Vec3> untouched = lattice;
    sim::compressHydrostatically(untouched, block, gravity, c0);
    for (std::size_t i = 0; i < untouched.size(); ++i) {
      EXPECT_EQ(untouched[i].x, lattice[i].x);
      EXPECT_EQ(untouched[i].y, lattice[i].y);
    }
  }
}

TEST(Sampling, RestingDensitiesFollowTheUncompressedDepth) {
  const double rho0 = 1000.0, c2 = kSoundSpeed * kSoundSpeed;
  const AxisBox block{{0.0, 0.0, 0.0}, {0.02, 0.1, 0.02}};
  const std::vector<Vec3> lattice = sim::sampleBlock(block, kSpacing);
  std::vector<Vec3> points = lattice;
  sim::compressHydrostatically(points, block, {0, -kG, 0}, kSoundSpeed);
  const std::vector<float> rho =
      sim::restingDensities(points, block, true, {0, -kG, 0}, kSoundSpeed, rho0);
  ASSERT_EQ(rho.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double depth = block.max[1] - lattice[i].y;
    EXPECT_NEAR(rho[i], rho0 * (1.0 + kG * depth / c2), 2e-3) << "depth " << depth;
  }
  // Not hydrostatic, or weightless: the rest density throughout.
  for (float r : sim::restingDensities(points, block, false, {0, -kG, 0}, kSoundSpeed, rho0))
    EXPECT_EQ(r, float(rho0));
  for (float r : sim::restingDensities(points, block, true, {0, 0, 0}, kSoundSpeed, rho0))
    EXPECT_EQ(r, float(rho0));
}

// The two together keep the mass of a column: each compressed layer, at its density, holds the
// mass of an uncompressed layer at the rest density, ρ Δz' = ρ0 d.
TEST(Sampling, CompressedLayersHoldTheMassOfUncompressedOnes) {
  const double rho0 = 1000.0;
  const AxisBox block{{0.0, 0.0, 0.0}, {0.01, 0.2, 0.01}};  // one column of 20 particles
  std::vector<Vec3> points = sim::sampleBlock(block, kSpacing);
  ASSERT_EQ(points.size(), 20u);
  sim::compressHydrostatically(points, block, {0, -kG, 0}, kSoundSpeed);
  const std::vector<float> rho =
      sim::restingDensities(points, block, true, {0, -kG, 0}, kSoundSpeed, rho0);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double gap = double(points[i + 1].y) - double(points[i].y);  // sampled bottom up
    const double between = 0.5 * (double(rho[i]) + double(rho[i + 1]));
    EXPECT_NEAR(gap * between / (rho0 * kSpacing), 1.0, 1e-4) << "layer " << i;
    if (i + 2 < points.size()) {  // deeper layers are squeezed more
      EXPECT_LT(gap, double(points[i + 2].y) - double(points[i + 1].y));
    }
  }
}

TEST(Sampling, UpIsTheAxisOfGravitysLargestComponent) {
  EXPECT_EQ(sim::upAxisOf({0, -9.81, 0}), 1);
  EXPECT_EQ(sim::upAxisOf({-9.81, 1.0, 0}), 0);
  EXPECT_EQ(sim::upAxisOf({3.0, 0, -9.81}), 2);
  EXPECT_EQ(sim::upAxisOf({0, 0, 9.81}), 2);
  EXPECT_EQ(sim::upAxisOf({0, 0, 0}), 1);  // none: y
}

}  // namespace
}  // namespace sph
