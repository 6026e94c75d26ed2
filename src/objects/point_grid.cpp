#include "objects/point_grid.hpp"

#include <limits>

namespace sph::objects {

void PointGrid::build(const std::vector<DVec3>& points, double cellSize) {
  const double big = std::numeric_limits<double>::infinity();
  build(points, cellSize, DVec3{-big, -big, -big}, DVec3{big, big, big});
}

void PointGrid::build(const std::vector<DVec3>& points, double cellSize, DVec3 regionMin,
                      DVec3 regionMax) {
  // NaN positions count as inside, so that a diverged run still lands in one cell.
  buildKept(points, cellSize, [&](std::size_t i) {
    const DVec3& p = points[i];
    return !(p.x < regionMin.x || p.y < regionMin.y || p.z < regionMin.z || p.x > regionMax.x ||
             p.y > regionMax.y || p.z > regionMax.z);
  });
}

void PointGrid::build(const std::vector<DVec3>& points, double cellSize,
                      const std::vector<std::uint8_t>& keep) {
  buildKept(points, cellSize, [&](std::size_t i) { return keep[i] != 0; });
}

template <class Keep>
void PointGrid::buildKept(const std::vector<DVec3>& points, double cellSize, Keep inside) {
  sorted_.clear();
  cellStart_.clear();
  std::size_t kept = 0;
  DVec3 lo{0, 0, 0}, hi{0, 0, 0};
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!inside(i)) continue;
    const DVec3& p = points[i];
    if (kept++ == 0) lo = hi = p;
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  if (kept == 0) return;
  // At most ~4 cells per point plus a small floor: memory stays linear in the point count.
  const double maxCells = 4.0 * double(kept) + 64.0;
  double cell = cellSize;
  auto cellsAlong = [&](double extent) { return std::floor(extent / cell) + 1.0; };
  const DVec3 extent = hi - lo;
  // Non-finite positions (a diverged run) all land in one cell instead of sizing the grid.
  const bool finite = std::isfinite(extent.x + extent.y + extent.z);
  if (!finite) cell = 1.0;
  while (finite && cellsAlong(extent.x) * cellsAlong(extent.y) * cellsAlong(extent.z) > maxCells)
    cell *= 2.0;
  origin_ = lo;
  inverseCell_ = 1.0 / cell;
  dims_[0] = finite ? int(cellsAlong(extent.x)) : 1;
  dims_[1] = finite ? int(cellsAlong(extent.y)) : 1;
  dims_[2] = finite ? int(cellsAlong(extent.z)) : 1;
  auto axisCell = [](double v, int dim) { return v >= 0.0 ? int(std::min(v, dim - 1.0)) : 0; };

  const std::size_t cellCount = std::size_t(dims_[0]) * dims_[1] * dims_[2];
  constexpr std::uint32_t kLeftOut = 0xffffffffu;
  std::vector<std::uint32_t> cellOf(points.size(), kLeftOut);
  cellStart_.assign(cellCount + 1, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!inside(i)) continue;
    const DVec3 c = (points[i] - origin_) * inverseCell_;
    const int x = axisCell(c.x, dims_[0]);
    const int y = axisCell(c.y, dims_[1]);
    const int z = axisCell(c.z, dims_[2]);
    cellOf[i] = std::uint32_t(cellIndex(x, y, z));
    ++cellStart_[cellOf[i] + 1];
  }
  for (std::size_t c = 0; c < cellCount; ++c) cellStart_[c + 1] += cellStart_[c];
  std::vector<std::uint32_t> next(cellStart_.begin(), cellStart_.end() - 1);
  sorted_.resize(kept);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (cellOf[i] != kLeftOut) sorted_[next[cellOf[i]]++] = std::uint32_t(i);
}

}  // namespace sph::objects
