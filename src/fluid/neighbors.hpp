// Visits the particles in the 27 cells around a position. Cells along x are adjacent in
// memory, so each row of three cells is one contiguous range (9 ranges, not 27).
#pragma once

#include <cstdint>

#include "fluid/particles.hpp"
#include "sph/core/grid.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

// Calls visitRange(begin, end) for each of the (up to) 9 rows of cells: [begin, end) indexes
// the particles sorted by cell.
//
// Along a periodic axis the rows wrap around: a row at either end of x is two ranges.
template <class VisitRange>
SPH_HD void forEachNeighborRangePeriodic(const GridSpec& grid, const std::uint32_t* cellStart,
                                         Int3 c, VisitRange&& visitRange) {
  const bool wrapX = grid.periodicAxes & 1u, wrapY = grid.periodicAxes & 2u,
             wrapZ = grid.periodicAxes & 4u;
  const auto wrap = [](int v, int dims) { return v < 0 ? v + dims : (v >= dims ? v - dims : v); };
  for (int dz = -1; dz <= 1; ++dz) {
    int z = c.z + dz;
    if (wrapZ) z = wrap(z, grid.dims.z);
    if (z < 0 || z >= grid.dims.z) continue;
    for (int dy = -1; dy <= 1; ++dy) {
      int y = c.y + dy;
      if (wrapY) y = wrap(y, grid.dims.y);
      if (y < 0 || y >= grid.dims.y) continue;
      const auto row = [&](int x0, int x1) {
        visitRange(readOnly(cellStart + cellIndex(grid, Int3{x0, y, z})),
                   readOnly(cellStart + cellIndex(grid, Int3{x1, y, z}) + 1));
      };
      const int last = grid.dims.x - 1;
      if (wrapX && c.x == 0) {
        row(last, last);
        row(0, 1);
      } else if (wrapX && c.x == last) {
        row(last - 1, last);
        row(0, 0);
      } else {
        row(c.x > 0 ? c.x - 1 : 0, c.x < last ? c.x + 1 : last);
      }
    }
  }
}

// The same for a position farther than a neighbour's reach from every periodic face (or in a
// grid without any): its rows never wrap. For a hot loop that decides wrapping once a particle,
// so that the visit is inlined into one walk only.
template <class VisitRange>
SPH_HD_INLINE void forEachNeighborRangeAwayFromSeams(const GridSpec& grid,
                                                     const std::uint32_t* cellStart, Vec3 p,
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

template <class VisitRange>
SPH_HD void forEachNeighborRange(const GridSpec& grid, const std::uint32_t* cellStart, Vec3 p,
                                 VisitRange&& visitRange) {
  if (grid.periodicAxes != 0)
    forEachNeighborRangePeriodic(grid, cellStart, clampToGrid(grid, cellCoordinate(grid, p)),
                                 visitRange);
  else
    forEachNeighborRangeAwayFromSeams(grid, cellStart, p, visitRange);
}

template <class Visit>
SPH_HD void forEachNeighbor(const GridSpec& grid, const std::uint32_t* cellStart, Vec3 p,
                            Visit&& visit) {
  forEachNeighborRange(grid, cellStart, p, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t j = begin; j < end; ++j) visit(j);
  });
}

// The same, over only the cells the ball (p, radius) touches: with a radius under the cell's
// size, 8 to 27 of them, and rows of 2 or 3 cells. For searches of a reach shorter than the
// grid's cell (an object particle's contact reach in the fluid's grid of cell h). The radius is
// padded by a few parts in a million so that rounding never leaves out a cell within reach.
template <class VisitRange>
SPH_HD void forEachNeighborRangeWithin(const GridSpec& grid, const std::uint32_t* cellStart, Vec3 p,
                                       float radius, VisitRange&& visitRange) {
  const float padded = radius * 1.00001f;
  const Int3 lo = cellCoordinate(grid, p - Vec3{padded, padded, padded});
  const Int3 hi = cellCoordinate(grid, p + Vec3{padded, padded, padded});
  if (hi.x < 0 || hi.y < 0 || hi.z < 0 || lo.x >= grid.dims.x || lo.y >= grid.dims.y ||
      lo.z >= grid.dims.z)
    return;
  const Int3 first = clampToGrid(grid, lo), last = clampToGrid(grid, hi);
  for (int z = first.z; z <= last.z; ++z)
    for (int y = first.y; y <= last.y; ++y) {
      const std::uint32_t begin = readOnly(cellStart + cellIndex(grid, Int3{first.x, y, z}));
      const std::uint32_t end = readOnly(cellStart + cellIndex(grid, Int3{last.x, y, z}) + 1);
      visitRange(begin, end);
    }
}

template <class Visit>
SPH_HD void forEachNeighborWithin(const GridSpec& grid, const std::uint32_t* cellStart, Vec3 p,
                                  float radius, Visit&& visit) {
  forEachNeighborRangeWithin(grid, cellStart, p, radius,
                             [&](std::uint32_t begin, std::uint32_t end) {
                               for (std::uint32_t j = begin; j < end; ++j) visit(j);
                             });
}

// The fluid neighbours the density pass listed, as the passes after it read them; the cells
// for a particle that had too many to list.
struct NeighborLists {
  const std::uint32_t* index;  // particle i's from i·stride
  const std::uint32_t* count;  // kNeighborOverflow: not listed
  std::uint32_t stride;
  GridSpec spec;
  const std::uint32_t* cellStart;
};

template <class B>
NeighborLists neighborLists(const FluidParticles<B>& fluid, const Grid<B>& grid) {
  return NeighborLists{fluid.neighbors.data(), fluid.neighborCount.data(), fluid.neighborStride,
                       grid.spec, grid.cellStart.data()};
}

// Calls visit(j) for each fluid neighbour j of particle i, itself left out: those listed, or
// every particle of the 27 cells for a particle with too many to list (visit tests the
// distance).
template <class Visit>
SPH_HD void forEachListedNeighbor(const NeighborLists& lists, std::size_t i, Vec3 xi,
                                  Visit&& visit) {
  const std::uint32_t count = lists.count[i];
  if (count != kNeighborOverflow) {
    const std::uint32_t* list = lists.index + i * lists.stride;
    for (std::uint32_t k = 0; k < count; ++k) visit(readOnly(list + k));
  } else {
    forEachNeighbor(lists.spec, lists.cellStart, xi, [&](std::uint32_t j) {
      if (j != i) visit(j);
    });
  }
}

// The static wall particles near a position, through their own grid; none when there are no
// walls.
struct WallCells {
  GridSpec spec;
  const std::uint32_t* cellStart;  // null: no walls
};

template <class B>
WallCells wallCells(const BoundaryParticles<B>& boundary) {
  return WallCells{boundary.grid, boundary.count != 0 ? boundary.cellStart.data() : nullptr};
}

// Whether x is within one cell of the grid, so that its 27 cells can hold a neighbour: a
// position farther out would be clamped to the edge and visit particles all out of reach.
SPH_HD_INLINE bool nearGrid(const GridSpec& g, Vec3 x) {
  const Int3 c = cellCoordinate(g, x);
  return c.x >= -1 && c.y >= -1 && c.z >= -1 && c.x <= g.dims.x && c.y <= g.dims.y &&
         c.z <= g.dims.z;
}

template <class Visit>
SPH_HD void forEachWallNeighbor(const WallCells& walls, Vec3 x, Visit&& visit) {
  if (walls.cellStart != nullptr && nearGrid(walls.spec, x))
    forEachNeighbor(walls.spec, walls.cellStart, x, visit);
}

}  // namespace sph::fluid
