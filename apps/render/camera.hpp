// An orbit camera around a target: what `sph render` frames a run with and what the viewer turns
// with the mouse (yaw, pitch, distance). Matrices are column-major float[16], as OpenGL takes
// them. No GL.
#pragma once

#include <array>

#include <vector>
#include "vec3f.hpp"

namespace sph::render {

using Mat4f = std::array<float, 16>;  // column-major: element (row r, column c) at [4c + r]

struct Box3f {
  Vec3f min{0, 0, 0}, max{0, 0, 0};
};

class OrbitCamera {
 public:
  Vec3f target{0, 0, 0};
  float distance = 1.0f;        // from target to eye
  float yaw = 0.0f;             // radians about +y; 0 looks along -z, with +x to the right
  float pitch = 0.0f;           // radians above the horizontal plane (positive looks down)
  float verticalFov = 0.6109f;  // radians (35°): little distortion at close range

  // A view from `yawDegrees` about +y and `pitchDegrees` above the horizontal (by default a 3/4
  // view from the front right and above), the box centred in the picture, at the least
  // distance that keeps its corners in sight for this aspect ratio (width / height), plus a margin.
  void frame(const Box3f& box, float aspect, float yawDegrees = kFrameYaw,
             float pitchDegrees = kFramePitch);
  // The same view, closer: every point in sight, what they cover centred in the picture.
  void frame(const std::vector<Vec3f>& points, float aspect, float yawDegrees = kFrameYaw,
             float pitchDegrees = kFramePitch);
  static constexpr float kFrameYaw = 35.0f, kFramePitch = 25.0f;

  Vec3f eye() const;
  Mat4f view() const;
  // Near and far planes follow the distance, so zooming in or out never clips the scene.
  Mat4f projection(float aspect) const;
};

// Applies a column-major matrix to the point (x, y, z, 1); returns (x, y, z, w).
std::array<float, 4> transformPoint(const Mat4f& m, const Vec3f& p);
Mat4f multiply(const Mat4f& a, const Mat4f& b);

}  // namespace sph::render
