// Visits the particles in the 27 cells around a position. Cells along x are adjacent in
// memory, so each row of three cells is one contiguous range (9 ranges, not 27).
#pragma once

#include <cstdint>

#include "sph/core/grid.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

// Calls visitRange(begin, end) for each of the (up to) 9 rows of cells: [begin, end) indexes
// the particles sorted by cell.
template <class VisitRange>
SPH_HD void forEachNeighborRange(const GridSpec& grid, const std::uint32_t* cellStart, Vec3 p,
                                 VisitRange&& visitRange) {
  const Int3 c = clampToGrid(grid, cellCoordinate(grid, p));
  const int x0 = c.x > 0 ? c.x - 1 : 0;
  const int x1 = c.x + 1 < grid.dims.x ? c.x + 1 : grid.dims.x - 1;
  for (int z = c.z - 1; z <= c.z + 1; ++z) {
    if (z < 0 || z >= grid.dims.z) continue;
    for (int y = c.y - 1; y <= c.y + 1; ++y) {
      if (y < 0 || y >= grid.dims.y) continue;
      const std::uint32_t begin = readOnly(cellStart + cellIndex(grid, Int3{x0, y, z}));
      const std::uint32_t end = readOnly(cellStart + cellIndex(grid, Int3{x1, y, z}) + 1);
      visitRange(begin, end);
    }
  }
}

template <class Visit>
SPH_HD void forEachNeighbor(const GridSpec& grid, const std::uint32_t* cellStart, Vec3 p,
                            Visit&& visit) {
  forEachNeighborRange(grid, cellStart, p, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t j = begin; j < end; ++j) visit(j);
  });
}

}  // namespace sph::fluid
