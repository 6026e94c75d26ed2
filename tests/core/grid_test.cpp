#include "sph/core/grid.hpp"

#include <gtest/gtest.h>

namespace sph {
namespace {

TEST(Grid, CoversTheBoxWithCellsOfTheGivenSize) {
  const GridSpec g = makeGrid(Vec3{0, 0, 0}, Vec3{1.0f, 0.5f, 0.25f}, 0.1f);
  EXPECT_EQ(g.dims.x, 11);
  EXPECT_EQ(g.dims.y, 6);
  EXPECT_EQ(g.dims.z, 3);
  EXPECT_EQ(g.cellCount, 11u * 6u * 3u);
  EXPECT_TRUE(insideGrid(g, cellCoordinate(g, Vec3{1.0f, 0.5f, 0.25f})));
}

TEST(Grid, CoordinatesFloorNegativeValues) {
  const GridSpec g = makeGrid(Vec3{0, 0, 0}, Vec3{1, 1, 1}, 0.1f);
  const Int3 c = cellCoordinate(g, Vec3{-0.05f, 0.15f, 0.99f});
  EXPECT_EQ(c.x, -1);
  EXPECT_EQ(c.y, 1);
  EXPECT_EQ(c.z, 9);
  EXPECT_FALSE(insideGrid(g, c));
  const Int3 clamped = clampToGrid(g, Int3{-3, 20, 4});
  EXPECT_EQ(clamped.x, 0);
  EXPECT_EQ(clamped.y, g.dims.y - 1);
  EXPECT_EQ(clamped.z, 4);
}

TEST(Grid, IndexIsRowMajorFromX) {
  const GridSpec g = makeGrid(Vec3{0, 0, 0}, Vec3{1, 1, 1}, 0.25f);
  EXPECT_EQ(cellIndex(g, Int3{0, 0, 0}), 0u);
  EXPECT_EQ(cellIndex(g, Int3{1, 0, 0}), 1u);
  EXPECT_EQ(cellIndex(g, Int3{0, 1, 0}), static_cast<std::uint32_t>(g.dims.x));
  EXPECT_EQ(cellIndex(g, Int3{0, 0, 1}), static_cast<std::uint32_t>(g.dims.x * g.dims.y));
  EXPECT_EQ(cellIndex(g, Int3{g.dims.x - 1, g.dims.y - 1, g.dims.z - 1}), g.cellCount - 1);
}

}  // namespace
}  // namespace sph
