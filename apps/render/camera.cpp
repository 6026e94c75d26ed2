#include "camera.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "sph/core/constants.hpp"

namespace sph::render {

namespace {

constexpr float kDegree = float(kPi / 180.0);

}  // namespace

void OrbitCamera::frame(const Box3f& box, float aspect, float yawDegrees, float pitchDegrees) {
  std::vector<Vec3f> corners;
  for (int corner = 0; corner < 8; ++corner)
    corners.push_back({corner & 1 ? box.max[0] : box.min[0], corner & 2 ? box.max[1] : box.min[1],
                       corner & 4 ? box.max[2] : box.min[2]});
  frame(corners, aspect, yawDegrees, pitchDegrees);
}

void OrbitCamera::frame(const std::vector<Vec3f>& points, float aspect, float yawDegrees,
                        float pitchDegrees) {
  yaw = yawDegrees * kDegree;
  pitch = pitchDegrees * kDegree;
  target = {0, 0, 0};
  if (points.empty()) return;
  Box3f box{points.front(), points.front()};
  for (const Vec3f& p : points)
    for (int c = 0; c < 3; ++c) {
      box.min[c] = std::min(box.min[c], p[c]);
      box.max[c] = std::max(box.max[c], p[c]);
    }
  for (int c = 0; c < 3; ++c) target[c] = 0.5f * (box.min[c] + box.max[c]);
  // The eye's axes, as in view().
  distance = 1.0f;
  const Vec3f toEye = normalize(subtract(eye(), target));
  const Vec3f forward{-toEye[0], -toEye[1], -toEye[2]};
  const Vec3f right = normalize(cross(forward, Vec3f{0, 1, 0}));
  const Vec3f up = cross(right, forward);
  const float tanVertical = std::tan(0.5f * verticalFov);
  const float tanHorizontal = tanVertical * aspect;
  // The least distance at which every point lies inside both half-angles of the view, then the
  // target moved across the view to centre what is seen, which changes that distance: a few
  // rounds settle both.
  // A bounding sphere would leave a long thin body (a vessel) small in the picture.
  for (int round = 0; round < 5; ++round) {
    float needed = 1e-6f;
    for (const Vec3f& p : points) {
      const Vec3f offset = subtract(p, target);
      const float towardEye = dot(offset, toEye);
      needed = std::max({needed, towardEye + std::abs(dot(offset, right)) / tanHorizontal,
                         towardEye + std::abs(dot(offset, up)) / tanVertical});
    }
    // 12 % more keeps particles at the edge (drawn as spheres of their own size) off the border.
    distance = 1.12f * needed;
    float low[2] = {1e30f, 1e30f}, high[2] = {-1e30f, -1e30f};
    for (const Vec3f& p : points) {
      const Vec3f offset = subtract(p, target);
      const float depth = distance - dot(offset, toEye);
      const float screen[2] = {dot(offset, right) / (depth * tanHorizontal),
                               dot(offset, up) / (depth * tanVertical)};
      for (int k = 0; k < 2; ++k) {
        low[k] = std::min(low[k], screen[k]);
        high[k] = std::max(high[k], screen[k]);
      }
    }
    if (round == 4) break;
    const float shiftRight = 0.5f * (low[0] + high[0]) * distance * tanHorizontal;
    const float shiftUp = 0.5f * (low[1] + high[1]) * distance * tanVertical;
    for (int c = 0; c < 3; ++c) target[c] += shiftRight * right[c] + shiftUp * up[c];
  }
}

Vec3f OrbitCamera::eye() const {
  const float c = std::cos(pitch);
  return {target[0] + distance * c * std::sin(yaw), target[1] + distance * std::sin(pitch),
          target[2] + distance * c * std::cos(yaw)};
}

Mat4f OrbitCamera::view() const {
  const Vec3f from = eye();
  const Vec3f forward = normalize(subtract(target, from));
  // Pitch is kept inside ±90° by the callers, so world up is never parallel to forward.
  const Vec3f right = normalize(cross(forward, Vec3f{0, 1, 0}));
  const Vec3f up = cross(right, forward);
  // clang-format off
  return {right[0], up[0], -forward[0], 0,
          right[1], up[1], -forward[1], 0,
          right[2], up[2], -forward[2], 0,
          -dot(right, from), -dot(up, from), dot(forward, from), 1};
  // clang-format on
}

Mat4f OrbitCamera::projection(float aspect) const {
  const float nearPlane = 0.01f * distance;
  const float farPlane = 100.0f * distance;
  const float f = 1.0f / std::tan(0.5f * verticalFov);
  Mat4f m{};
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (farPlane + nearPlane) / (nearPlane - farPlane);
  m[11] = -1.0f;
  m[14] = 2.0f * farPlane * nearPlane / (nearPlane - farPlane);
  return m;
}

std::array<float, 4> transformPoint(const Mat4f& m, const Vec3f& p) {
  std::array<float, 4> out{};
  for (int r = 0; r < 4; ++r) out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
  return out;
}

Mat4f multiply(const Mat4f& a, const Mat4f& b) {
  Mat4f out{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) out[4 * c + r] += a[4 * k + r] * b[4 * c + k];
  return out;
}

}  // namespace sph::render
