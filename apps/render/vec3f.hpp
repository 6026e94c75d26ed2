// The renderer's small vectors (single precision, as OpenGL takes them) and their arithmetic,
// shared by the camera and the viewer's picking.
#pragma once

#include <array>
#include <cmath>

namespace sph::render {

using Vec3f = std::array<float, 3>;

inline Vec3f add(const Vec3f& a, const Vec3f& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3f subtract(const Vec3f& a, const Vec3f& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3f scale(const Vec3f& a, float s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
inline float dot(const Vec3f& a, const Vec3f& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3f cross(const Vec3f& a, const Vec3f& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// Unit length; the zero vector stays zero.
inline Vec3f normalize(const Vec3f& a) {
  const float length = std::sqrt(dot(a, a));
  return length > 0 ? Vec3f{a[0] / length, a[1] / length, a[2] / length} : a;
}

}  // namespace sph::render
