#include "scene/scene_checks.hpp"
#include "sph/error.hpp"

#include <cmath>
#include <utility>

namespace sph::scene {

double lengthOf(const Vec3d& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

void checkPointInDomain(const ReadContext& context, const Vec3d& x, const std::string& key,
                        const AxisBox& domain) {
  for (int axis = 0; axis < 3; ++axis) {
    if (x[axis] < domain.min[axis] || x[axis] > domain.max[axis])
      context.fail(key,
                   "expected a point inside the domain box " + formatVec3(domain.min) + " to " +
                       formatVec3(domain.max) + ", got " + formatVec3(x),
                   {"domain.min", "domain.max"});
  }
}

void checkBoxOrder(const ReadContext& context, const AxisBox& box, const std::string& path) {
  const std::string minKey = joinKey(path, "min");
  for (int axis = 0; axis < 3; ++axis) {
    if (!(box.max[axis] > box.min[axis])) {
      context.fail(joinKey(path, "max"),
                   "expected a point above " + minKey + " " + formatVec3(box.min) +
                       " on every axis, got " + formatVec3(box.max),
                   {minKey});
    }
  }
}

void checkInsideDomain(const ReadContext& context, const AxisBox& box, const std::string& path,
                       const AxisBox& domain) {
  const std::pair<const char*, const Vec3d*> corners[] = {{"min", &box.min}, {"max", &box.max}};
  for (const auto& [key, corner] : corners) {
    for (int axis = 0; axis < 3; ++axis) {
      const double x = (*corner)[axis];
      if (x < domain.min[axis] || x > domain.max[axis]) {
        context.fail(joinKey(path, key),
                     "expected a point inside the domain box " + formatVec3(domain.min) + " to " +
                         formatVec3(domain.max) + ", got " + formatVec3(*corner),
                     {"domain.min", "domain.max"});
      }
    }
  }
}

// Below one spacing the sampling has nothing to lay out.
void checkAtLeastSpacing(const ReadContext& context, double value, const std::string& key,
                         double spacing) {
  if (!(value >= spacing))
    context.fail(key,
                 "expected at least the fluid's spacing " + formatNumber(spacing) + " m, got " +
                     formatNumber(value),
                 {"fluid.spacing"});
}

void checkNotParallel(const ReadContext& context, const Vec3d& edge1, const Vec3d& edge2,
                      const std::string& edge1Key, const std::string& key) {
  if (!(lengthOf(cross(edge1, edge2)) > 1e-6 * lengthOf(edge1) * lengthOf(edge2)))
    context.fail(key,
                 "expected an edge not parallel to " + edge1Key + " " + formatVec3(edge1) +
                     ", got " + formatVec3(edge2),
                 {edge1Key});
}

}  // namespace sph::scene
