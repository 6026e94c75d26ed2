// Tests against the scene's axis-aligned boxes (a deformable's pinned regions and cuts).
#pragma once

#include <algorithm>

#include "objects/math3d.hpp"
#include "sph/scene.hpp"

namespace sph::objects {

// Whether the segment from a to b passes through the box (the slab test).
inline bool segmentMeetsBox(const AxisBox& box, DVec3 a, DVec3 b) {
  const double from[3] = {a.x, a.y, a.z}, to[3] = {b.x, b.y, b.z};
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = to[axis] - from[axis];
    if (d == 0.0) {
      if (from[axis] < box.min[axis] || from[axis] > box.max[axis]) return false;
      continue;
    }
    double t0 = (box.min[axis] - from[axis]) / d, t1 = (box.max[axis] - from[axis]) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return false;
  }
  return true;
}

inline bool insideBox(const AxisBox& box, DVec3 p) {
  return p.x >= box.min[0] && p.x <= box.max[0] && p.y >= box.min[1] && p.y <= box.max[1] &&
         p.z >= box.min[2] && p.z <= box.max[2];
}

}  // namespace sph::objects
