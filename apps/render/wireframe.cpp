#include "wireframe.hpp"

#include <cmath>

namespace sph::render {

namespace {

void addLine(std::vector<float>& lines, const Vec3f& a, const Vec3f& b) {
  lines.insert(lines.end(), {a[0], a[1], a[2], b[0], b[1], b[2]});
}

}  // namespace

std::vector<float> boxEdges(const Box3f& box) {
  std::vector<float> lines;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int corner = 0; corner < 4; ++corner) {
      Vec3f a{}, b{};
      a[u] = b[u] = corner & 1 ? box.max[u] : box.min[u];
      a[v] = b[v] = corner & 2 ? box.max[v] : box.min[v];
      a[axis] = box.min[axis];
      b[axis] = box.max[axis];
      addLine(lines, a, b);
    }
  }
  return lines;
}

std::vector<float> gridOnBackFaces(const Box3f& box, float cellSize, const Vec3f& eye,
                                   int maxCells) {
  std::vector<float> lines;
  if (!(cellSize > 0.0f)) return lines;
  int cells[3];
  for (int axis = 0; axis < 3; ++axis) {
    const float extent = box.max[axis] - box.min[axis];
    cells[axis] = static_cast<int>(std::ceil(extent / cellSize - 1e-4f));
    if (cells[axis] > maxCells || cells[axis] < 1) return {};
  }
  for (int normal = 0; normal < 3; ++normal) {
    // The face farther from the eye along this axis.
    const float centre = 0.5f * (box.min[normal] + box.max[normal]);
    const float face = eye[normal] > centre ? box.min[normal] : box.max[normal];
    const int u = (normal + 1) % 3, v = (normal + 2) % 3;
    for (int pass = 0; pass < 2; ++pass) {
      const int along = pass == 0 ? u : v, across = pass == 0 ? v : u;
      for (int k = 0; k <= cells[along]; ++k) {
        Vec3f a{}, b{};
        a[normal] = b[normal] = face;
        a[along] = b[along] =
            std::fmin(box.min[along] + static_cast<float>(k) * cellSize, box.max[along]);
        a[across] = box.min[across];
        b[across] = box.max[across];
        addLine(lines, a, b);
      }
    }
  }
  return lines;
}

}  // namespace sph::render
