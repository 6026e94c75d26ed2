// The density solve's coarse level (src/fluid/coarse_pressure.hpp) on a water column in a tank:
// the pressure a uniform compression asks for grows with depth as the continuum equation says,
// is zero at the surface, and is not asked for where nothing compresses or where the fluid has no
// free surface.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fluid/coarse_pressure.hpp"

namespace sph::fluid {
namespace {

constexpr float kSpacing = 0.01f;
constexpr float kRestDensity = 1000.0f;
constexpr float kDt = 2e-3f;

// Water `depth` deep filling a tank 0.32 m square (particles at half-spacing offsets), its
// floor and four sides four layers of wall particles (a coarse cell: a thinner wall leaves the
// cells past it empty, and they read as surface), and a lid if `closed`.
struct Column {
  std::vector<Vec4> fluid, wall;
  std::vector<float> density, error;
  GridSpec grid{};

  Column(float depth, float error0, bool closed) {
    const float width = 0.32f;
    const auto lattice = [&](float x0, float x1, float y0, float y1, auto&& add) {
      for (float x = x0 + 0.5f * kSpacing; x < x1; x += kSpacing)
        for (float y = y0 + 0.5f * kSpacing; y < y1; y += kSpacing)
          for (float z = x0 + 0.5f * kSpacing; z < x1; z += kSpacing) add(x, y, z);
    };
    lattice(0.0f, width, 0.0f, depth, [&](float x, float y, float z) {
      fluid.push_back(Vec4{x, y, z, 0.0f});
    });
    const float layers = 4.0f;
    const float top = closed ? depth + layers * kSpacing : depth + 0.1f;
    lattice(-layers * kSpacing, width + layers * kSpacing, -layers * kSpacing, top,
            [&](float x, float y, float z) {
              const bool inTank = x > 0.0f && x < width && z > 0.0f && z < width && y > 0.0f;
              const bool underLid = y < depth || !closed;
              if (!(inTank && underLid))
                wall.push_back(Vec4{x, y, z, kSpacing * kSpacing * kSpacing});
            });
    density.assign(fluid.size(), kRestDensity);
    error.assign(fluid.size(), error0);
    const float h = 2.0f * kSpacing;
    grid.origin = Vec3{-0.05f, -0.05f, -0.05f};
    grid.cellSize = h;
    grid.inverseCellSize = 1.0f / h;
    grid.dims = Int3{22, 30, 22};
    grid.cellCount = std::uint32_t(grid.dims.x * grid.dims.y * grid.dims.z);
  }

  CoarseInput input() const {
    CoarseInput in;
    in.fineGrid = grid;
    in.position = fluid.data();
    in.density = density.data();
    in.error = error.data();
    in.count = fluid.size();
    in.wall = wall.data();
    in.wallCount = wall.size();
    in.particleVolume = kSpacing * kSpacing * kSpacing;
    in.restDensity = kRestDensity;
    in.dt = kDt;
    return in;
  }
};

TEST(CoarsePressure, AUniformCompressionAsksForAPressureGrowingWithDepth) {
  const float depth = 0.32f, error0 = 1e-3f;
  const Column column(depth, error0, /*closed=*/false);
  CoarsePressure coarse;
  std::vector<float> k(column.fluid.size(), -1.0f);
  ASSERT_TRUE(coarse.solve(column.input(), k.data()));

  // Down the middle of the tank: none in the cell under the surface, then rising to the floor.
  std::vector<std::pair<float, float>> profile;  // (height, K)
  for (std::size_t i = 0; i < column.fluid.size(); ++i) {
    const Vec4 p = column.fluid[i];
    EXPECT_GE(k[i], 0.0f);
    if (std::abs(p.x - 0.155f) < 1e-4f && std::abs(p.z - 0.155f) < 1e-4f)
      profile.push_back({p.y, k[i]});
  }
  ASSERT_EQ(profile.size(), 32u);
  EXPECT_EQ(profile.back().second, 0.0f) << "the top layer is at the free surface";
  for (std::size_t j = 1; j < profile.size(); ++j)
    EXPECT_LE(profile[j].second, profile[j - 1].second) << "at y = " << profile[j].first;

  // The continuum: Δt² ρ0 K'' = -e0, K = 0 at the surface, K' = 0 at the floor, gives
  // K(floor) = e0 D² / (2 Δt² ρ0) over a depth D. The coarse level takes the surface two or three
  // cells (0.04 m each) lower, and so asks for less: between (D - 3 cells)² and D² of it.
  const double full = error0 * double(depth) * depth / (2.0 * kDt * kDt * kRestDensity);
  const double lowered =
      error0 * double(depth - 0.12) * (depth - 0.12) / (2.0 * kDt * kDt * kRestDensity);
  EXPECT_LT(profile.front().second, full);
  EXPECT_GT(profile.front().second, lowered);

  // The side walls take no flux: a layer's K is the same across the tank, away from the walls
  // (within what conjugate gradients stopping at a residual of 10⁻⁴ leave: 1.0 % measured).
  for (std::size_t i = 0; i < column.fluid.size(); ++i) {
    const Vec4 p = column.fluid[i];
    const bool inner = p.x > 0.06f && p.x < 0.26f && p.z > 0.06f && p.z < 0.26f;
    if (!inner || std::abs(p.y - profile.front().first) > 1e-4f) continue;
    EXPECT_NEAR(k[i], profile.front().second, 0.02 * profile.front().second);
  }
}

TEST(CoarsePressure, NothingCompressedAsksForNothing) {
  for (const float error0 : {0.0f, -2e-3f}) {
    const Column column(0.24f, error0, /*closed=*/false);
    CoarsePressure coarse;
    std::vector<float> k(column.fluid.size(), -1.0f);
    ASSERT_TRUE(coarse.solve(column.input(), k.data()));
    for (float ki : k) ASSERT_EQ(ki, 0.0f) << "error " << error0;
  }
}

TEST(CoarsePressure, FluidWithoutAFreeSurfaceIsLeftToJacobi) {
  const Column column(0.24f, 1e-3f, /*closed=*/true);
  CoarsePressure coarse;
  std::vector<float> k(column.fluid.size(), -1.0f);
  EXPECT_FALSE(coarse.solve(column.input(), k.data()));
  for (float ki : k) ASSERT_EQ(ki, -1.0f) << "written where nothing was solved";
}

}  // namespace
}  // namespace sph::fluid
