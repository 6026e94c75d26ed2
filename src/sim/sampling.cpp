#include "sim/sampling.hpp"

#include <cmath>

namespace sph::sim {

namespace {

int cellsAlong(double extent, double spacing) {
  return static_cast<int>(std::lround(extent / spacing));
}

}  // namespace

std::vector<Vec3> sampleBlock(const AxisBox& box, double spacing) {
  const int nx = cellsAlong(box.max[0] - box.min[0], spacing);
  const int ny = cellsAlong(box.max[1] - box.min[1], spacing);
  const int nz = cellsAlong(box.max[2] - box.min[2], spacing);
  std::vector<Vec3> points;
  if (nx <= 0 || ny <= 0 || nz <= 0) return points;
  points.reserve(static_cast<std::size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        points.push_back(Vec3{static_cast<float>(box.min[0] + (i + 0.5) * spacing),
                              static_cast<float>(box.min[1] + (j + 0.5) * spacing),
                              static_cast<float>(box.min[2] + (k + 0.5) * spacing)});
  return points;
}

std::vector<Vec3> sampleTank(const AxisBox& inner, int layers, bool closed, double spacing,
                             const Vec3d& gravity) {
  const int upAxis = upAxisOf(gravity);
  const bool upIsPositive = gravity[upAxis] <= 0.0;
  int n[3];
  for (int a = 0; a < 3; ++a) n[a] = cellsAlong(inner.max[a] - inner.min[a], spacing);
  std::vector<Vec3> points;
  for (int k = -layers; k < n[2] + layers; ++k)
    for (int j = -layers; j < n[1] + layers; ++j)
      for (int i = -layers; i < n[0] + layers; ++i) {
        const int index[3] = {i, j, k};
        bool inside = true;
        for (int a = 0; a < 3; ++a) inside = inside && index[a] >= 0 && index[a] < n[a];
        if (inside) continue;
        // No lid: nothing beyond the rim on the side gravity points away from.
        if (!closed && (upIsPositive ? index[upAxis] >= n[upAxis] : index[upAxis] < 0)) continue;
        points.push_back(Vec3{static_cast<float>(inner.min[0] + (i + 0.5) * spacing),
                              static_cast<float>(inner.min[1] + (j + 0.5) * spacing),
                              static_cast<float>(inner.min[2] + (k + 0.5) * spacing)});
      }
  return points;
}

void compressHydrostatically(std::vector<Vec3>& points, const AxisBox& block, const Vec3d& gravity,
                             double soundSpeed) {
  const int up = upAxisOf(gravity);
  const double g = std::abs(gravity[up]);
  if (g == 0.0 || soundSpeed <= 0.0) return;
  const bool upIsPositive = gravity[up] <= 0.0;
  const double top = upIsPositive ? block.max[up] : block.min[up];
  const double c2 = soundSpeed * soundSpeed;
  for (Vec3& p : points) {
    float* coordinate = up == 0 ? &p.x : (up == 1 ? &p.y : &p.z);
    const double depth = std::abs(top - double(*coordinate));
    const double compressed = c2 / g * std::log1p(g * depth / c2);
    *coordinate = static_cast<float>(upIsPositive ? top - compressed : top + compressed);
  }
}

std::vector<float> restingDensities(const std::vector<Vec3>& points, const AxisBox& block,
                                    bool hydrostatic, const Vec3d& gravity, double soundSpeed,
                                    double restDensity) {
  std::vector<float> out(points.size(), float(restDensity));
  const int up = upAxisOf(gravity);
  const double g = std::abs(gravity[up]);
  if (!hydrostatic || g == 0.0 || soundSpeed <= 0.0) return out;
  const bool upIsPositive = gravity[up] <= 0.0;
  const double top = upIsPositive ? block.max[up] : block.min[up];
  const double c2 = soundSpeed * soundSpeed;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    const double compressed = std::abs(top - double(up == 0 ? p.x : (up == 1 ? p.y : p.z)));
    const double depth = c2 / g * std::expm1(g * compressed / c2);  // compressHydrostatically's z
    out[i] = float(restDensity * (1.0 + g * depth / c2));
  }
  return out;
}

int upAxisOf(const Vec3d& gravity) {
  int axis = 1;
  double largest = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(gravity[a]) > largest) {
      largest = std::abs(gravity[a]);
      axis = a;
    }
  }
  return axis;
}

}  // namespace sph::sim
