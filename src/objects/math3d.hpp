// Double-precision vectors, 3×3 matrices and unit quaternions for the object engine's host-side
// state (centres of mass, orientations, deformable particles). Published particle data stays
// float (ParticleState); integrating in double keeps long runs and rotations accurate.
#pragma once

#include <cmath>

#include "sph/core/vec.hpp"
#include "sph/scene.hpp"

namespace sph::objects {

struct DVec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

inline DVec3 operator+(DVec3 a, DVec3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline DVec3 operator-(DVec3 a, DVec3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline DVec3 operator-(DVec3 a) {
  return {-a.x, -a.y, -a.z};
}
inline DVec3 operator*(DVec3 a, double s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline DVec3 operator*(double s, DVec3 a) {
  return a * s;
}
inline DVec3 operator/(DVec3 a, double s) {
  return a * (1.0 / s);
}
inline DVec3& operator+=(DVec3& a, DVec3 b) {
  return a = a + b;
}
inline DVec3& operator-=(DVec3& a, DVec3 b) {
  return a = a - b;
}
inline double dot(DVec3 a, DVec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline DVec3 cross(DVec3 a, DVec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(DVec3 a) {
  return std::sqrt(dot(a, a));
}
// The zero vector stays zero.
inline DVec3 normalized(DVec3 a) {
  const double n = norm(a);
  return n > 0.0 ? a / n : a;
}

inline DVec3 toD(Vec3 v) {
  return {v.x, v.y, v.z};
}
inline DVec3 toD(const Vec3d& v) {
  return {v[0], v[1], v[2]};
}
inline Vec3 toF(DVec3 v) {
  return Vec3{float(v.x), float(v.y), float(v.z)};
}

// Two unit vectors completing the unit `axis` to a right-handed orthonormal frame (u, v, axis).
inline void perpendicularFrame(DVec3 axis, DVec3& u, DVec3& v) {
  const DVec3 helper = std::abs(axis.x) < 0.9 ? DVec3{1, 0, 0} : DVec3{0, 1, 0};
  u = normalized(cross(axis, helper));
  v = cross(axis, u);
}

// Row-major 3×3 matrix.
struct Mat3 {
  double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};

  static Mat3 identity() {
    Mat3 r;
    r.m[0][0] = r.m[1][1] = r.m[2][2] = 1.0;
    return r;
  }
};

inline DVec3 operator*(const Mat3& a, DVec3 v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
          a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}
inline Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r.m[i][j] += a.m[i][k] * b.m[k][j];
  return r;
}
inline Mat3 transpose(const Mat3& a) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[j][i];
  return r;
}
// Inverse by cofactors; the caller guarantees a non-singular matrix.
inline Mat3 inverse(const Mat3& a) {
  const auto& m = a.m;
  Mat3 c;
  c.m[0][0] = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  c.m[0][1] = m[0][2] * m[2][1] - m[0][1] * m[2][2];
  c.m[0][2] = m[0][1] * m[1][2] - m[0][2] * m[1][1];
  c.m[1][0] = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  c.m[1][1] = m[0][0] * m[2][2] - m[0][2] * m[2][0];
  c.m[1][2] = m[0][2] * m[1][0] - m[0][0] * m[1][2];
  c.m[2][0] = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  c.m[2][1] = m[0][1] * m[2][0] - m[0][0] * m[2][1];
  c.m[2][2] = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  const double det = m[0][0] * c.m[0][0] + m[0][1] * c.m[1][0] + m[0][2] * c.m[2][0];
  for (auto& row : c.m)
    for (double& v : row) v /= det;
  return c;
}
// [v]×, the matrix of v × ·.
inline Mat3 crossMatrix(DVec3 v) {
  Mat3 r;
  r.m[0][1] = -v.z;
  r.m[0][2] = v.y;
  r.m[1][0] = v.z;
  r.m[1][2] = -v.x;
  r.m[2][0] = -v.y;
  r.m[2][1] = v.x;
  return r;
}
inline Mat3 operator+(const Mat3& a, const Mat3& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][j] + b.m[i][j];
  return r;
}
inline Mat3 operator*(const Mat3& a, double s) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][j] * s;
  return r;
}

// Rotation by the rotation vector θ (axis × angle), Rodrigues' formula:
// R = I + sin|θ|/|θ| [θ]× + (1 − cos|θ|)/|θ|² [θ]×².
inline Mat3 rotationFromVector(DVec3 theta) {
  const double angle = norm(theta);
  const Mat3 k = crossMatrix(theta);
  if (angle < 1e-12) return Mat3::identity() + k;
  return Mat3::identity() + k * (std::sin(angle) / angle) +
         (k * k) * ((1.0 - std::cos(angle)) / (angle * angle));
}

// The left Jacobian of SO(3): for R(t) = exp([θ(t)]×) the spatial angular velocity is
// ω = J(θ) θ̇ (Ṙ Rᵀ = [ω]×), J = I + (1 − cos|θ|)/|θ|² [θ]× + (|θ| − sin|θ|)/|θ|³ [θ]×².
inline Mat3 leftJacobian(DVec3 theta) {
  const double angle = norm(theta);
  const Mat3 k = crossMatrix(theta);
  if (angle < 1e-8) return Mat3::identity() + k * 0.5;
  const double a2 = angle * angle;
  return Mat3::identity() + k * ((1.0 - std::cos(angle)) / a2) +
         (k * k) * ((angle - std::sin(angle)) / (a2 * angle));
}

// Unit quaternion w + (x, y, z) for orientations (body → world).
struct Quat {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

inline Quat operator*(Quat a, Quat b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
inline Quat normalized(Quat q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}
inline Mat3 rotationMatrix(Quat q) {
  Mat3 r;
  r.m[0][0] = 1 - 2 * (q.y * q.y + q.z * q.z);
  r.m[0][1] = 2 * (q.x * q.y - q.w * q.z);
  r.m[0][2] = 2 * (q.x * q.z + q.w * q.y);
  r.m[1][0] = 2 * (q.x * q.y + q.w * q.z);
  r.m[1][1] = 1 - 2 * (q.x * q.x + q.z * q.z);
  r.m[1][2] = 2 * (q.y * q.z - q.w * q.x);
  r.m[2][0] = 2 * (q.x * q.z - q.w * q.y);
  r.m[2][1] = 2 * (q.y * q.z + q.w * q.x);
  r.m[2][2] = 1 - 2 * (q.x * q.x + q.y * q.y);
  return r;
}

}  // namespace sph::objects
