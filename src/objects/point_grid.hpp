// A uniform grid over a set of points for fixed-radius neighbour queries, rebuilt from scratch
// whenever the points move. Points are sorted into cells by a counting sort that keeps index
// order inside each cell, so every query visits candidates in the same order on every run.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "objects/math3d.hpp"

namespace sph::objects {

class PointGrid {
 public:
  // Sorts `points` into cubic cells of edge at least `cellSize` over their bounding box. When
  // the points are spread so far apart that the box would need many more cells than points,
  // the cells grow (queries stay exact, only coarser).
  void build(const std::vector<DVec3>& points, double cellSize);
  // The same over the points inside [regionMin, regionMax] only: a few points far away (a piece
  // torn off and falling) neither coarsen the cells nor are found.
  void build(const std::vector<DVec3>& points, double cellSize, DVec3 regionMin, DVec3 regionMax);
  // The same over the points whose `keep` entry is not 0.
  void build(const std::vector<DVec3>& points, double cellSize,
             const std::vector<std::uint8_t>& keep);

  // Calls visit(index) for every point in the cells that the ball (p, radius) touches; the
  // caller tests the distance.
  template <class Visit>
  void forEachCandidate(DVec3 p, double radius, Visit&& visit) const {
    if (sorted_.empty()) return;
    int lo[3], hi[3];
    const double c[3] = {p.x - origin_.x, p.y - origin_.y, p.z - origin_.z};
    for (int a = 0; a < 3; ++a) {
      const double first = std::floor((c[a] - radius) * inverseCell_);
      const double last = std::floor((c[a] + radius) * inverseCell_);
      if (!(last >= 0.0 && first < double(dims_[a]))) return;  // outside, or NaN
      lo[a] = int(std::max(first, 0.0));
      hi[a] = int(std::min(last, double(dims_[a] - 1)));
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const std::size_t cell = cellIndex(x, y, z);
          for (std::uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) visit(sorted_[k]);
        }
  }

 private:
  template <class Keep>
  void buildKept(const std::vector<DVec3>& points, double cellSize, Keep inside);
  std::size_t cellIndex(int x, int y, int z) const {
    return std::size_t(x) + std::size_t(dims_[0]) * (std::size_t(y) + std::size_t(dims_[1]) * z);
  }

  DVec3 origin_;
  double inverseCell_ = 1.0;
  int dims_[3] = {1, 1, 1};
  std::vector<std::uint32_t> cellStart_;  // cellCount + 1 offsets into sorted_
  std::vector<std::uint32_t> sorted_;     // point indices, by cell, ascending within a cell
};

}  // namespace sph::objects
