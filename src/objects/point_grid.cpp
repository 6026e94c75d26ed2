#include "objects/point_grid.hpp"

namespace sph::objects {

void PointGrid::build(const std::vector<DVec3>& points, double cellSize) {
  sorted_.clear();
  cellStart_.clear();
  if (points.empty()) return;
  DVec3 lo = points[0], hi = points[0];
  for (const DVec3& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  // At most ~4 cells per point plus a small floor: memory stays linear in the point count.
  const double maxCells = 4.0 * double(points.size()) + 64.0;
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
  std::vector<std::uint32_t> cellOf(points.size());
  cellStart_.assign(cellCount + 1, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const DVec3 c = (points[i] - origin_) * inverseCell_;
    const int x = axisCell(c.x, dims_[0]);
    const int y = axisCell(c.y, dims_[1]);
    const int z = axisCell(c.z, dims_[2]);
    cellOf[i] = std::uint32_t(cellIndex(x, y, z));
    ++cellStart_[cellOf[i] + 1];
  }
  for (std::size_t c = 0; c < cellCount; ++c) cellStart_[c + 1] += cellStart_[c];
  std::vector<std::uint32_t> next(cellStart_.begin(), cellStart_.end() - 1);
  sorted_.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) sorted_[next[cellOf[i]]++] = std::uint32_t(i);
}

}  // namespace sph::objects
