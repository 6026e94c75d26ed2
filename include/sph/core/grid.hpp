// Uniform grid cell arithmetic. Cells are cubes of edge `cellSize` (= h) from `origin`;
// a cell index is x + dims.x (y + dims.y z). Along a periodic axis the grid spans the period
// exactly: its last cell takes what is left of the period (from one to two cell edges), and
// the cells on either end are neighbours.
#pragma once

#include <cstdint>

#include "sph/core/vec.hpp"

namespace sph {

struct GridSpec {
  Vec3 origin;
  float cellSize;
  float inverseCellSize;
  Int3 dims;
  std::uint32_t cellCount;
  std::uint32_t periodicAxes = 0;  // bit a: axis a wraps around (x 1, y 2, z 4)
};

SPH_HD_INLINE int floorToInt(float v) {
  const int i = static_cast<int>(v);
  return (v < static_cast<float>(i)) ? i - 1 : i;
}

// Not clamped: the caller decides what a position outside the grid means.
SPH_HD_INLINE Int3 cellCoordinate(const GridSpec& g, Vec3 p) {
  return Int3{floorToInt((p.x - g.origin.x) * g.inverseCellSize),
              floorToInt((p.y - g.origin.y) * g.inverseCellSize),
              floorToInt((p.z - g.origin.z) * g.inverseCellSize)};
}

SPH_HD_INLINE bool insideGrid(const GridSpec& g, Int3 c) {
  return c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < g.dims.x && c.y < g.dims.y && c.z < g.dims.z;
}

SPH_HD_INLINE int clampInt(int v, int lo, int hi) {
  return v < lo ? lo : (v > hi ? hi : v);
}

SPH_HD_INLINE Int3 clampToGrid(const GridSpec& g, Int3 c) {
  return Int3{clampInt(c.x, 0, g.dims.x - 1), clampInt(c.y, 0, g.dims.y - 1),
              clampInt(c.z, 0, g.dims.z - 1)};
}

SPH_HD_INLINE std::uint32_t cellIndex(const GridSpec& g, Int3 c) {
  return static_cast<std::uint32_t>(c.x) +
         static_cast<std::uint32_t>(g.dims.x) *
             (static_cast<std::uint32_t>(c.y) +
              static_cast<std::uint32_t>(g.dims.y) * static_cast<std::uint32_t>(c.z));
}

// A grid of cell edge `cellSize` covering [lo, hi]; at least one cell per axis.
inline GridSpec makeGrid(Vec3 lo, Vec3 hi, float cellSize) {
  auto cells = [&](float extent) {
    const int n = static_cast<int>(extent / cellSize) + 1;
    return n < 1 ? 1 : n;
  };
  GridSpec g;
  g.origin = lo;
  g.cellSize = cellSize;
  g.inverseCellSize = 1.0f / cellSize;
  g.dims = Int3{cells(hi.x - lo.x), cells(hi.y - lo.y), cells(hi.z - lo.z)};
  g.cellCount = static_cast<std::uint32_t>(g.dims.x) * static_cast<std::uint32_t>(g.dims.y) *
                static_cast<std::uint32_t>(g.dims.z);
  return g;
}

// The same, over [lo, hi] along the axes that are not periodic, and over exactly the period
// [periodLo, periodHi) along those that are: floor(period / cellSize) cells there, at least 3
// (fewer would visit a cell twice as a neighbour from both sides; the caller refuses them).
inline GridSpec makePeriodicGrid(Vec3 lo, Vec3 hi, float cellSize, std::uint32_t periodicAxes,
                                 Vec3 periodLo, Vec3 periodHi) {
  GridSpec g = makeGrid(lo, hi, cellSize);
  g.periodicAxes = periodicAxes;
  const auto along = [&](int axis, float& origin, int& dims, float periodLow, float periodHigh) {
    if (!((periodicAxes >> axis) & 1u)) return;
    origin = periodLow;
    const int n = static_cast<int>((periodHigh - periodLow) / cellSize);
    dims = n < 3 ? 3 : n;
  };
  along(0, g.origin.x, g.dims.x, periodLo.x, periodHi.x);
  along(1, g.origin.y, g.dims.y, periodLo.y, periodHi.y);
  along(2, g.origin.z, g.dims.z, periodLo.z, periodHi.z);
  g.cellCount = static_cast<std::uint32_t>(g.dims.x) * static_cast<std::uint32_t>(g.dims.y) *
                static_cast<std::uint32_t>(g.dims.z);
  return g;
}

}  // namespace sph
