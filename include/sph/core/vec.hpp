// Small vector types shared by host and device code. Vec4 pads a Vec3 to 16 bytes so
// positions and velocities load as one aligned word (Meteer 2011, §2.4).
#pragma once

#include <cmath>

#include "sph/core/hostdevice.hpp"

namespace sph {

struct Vec3 {
  float x, y, z;
};

struct alignas(16) Vec4 {
  float x, y, z, w;
};

struct Int3 {
  int x, y, z;
};

// Overloads, not templates, so a SIMD batch type can add its own.
SPH_HD float realSqrt(float v) {
  return sqrtf(v);
}
SPH_HD double realSqrt(double v) {
  return sqrt(v);
}

SPH_HD Vec3 makeVec3(float x, float y, float z) {
  return Vec3{x, y, z};
}
SPH_HD Vec3 xyz(const Vec4& v) {
  return Vec3{v.x, v.y, v.z};
}
SPH_HD Vec4 makeVec4(const Vec3& v, float w = 0.0f) {
  return Vec4{v.x, v.y, v.z, w};
}

SPH_HD Vec3 operator+(Vec3 a, Vec3 b) {
  return Vec3{a.x + b.x, a.y + b.y, a.z + b.z};
}
SPH_HD Vec3 operator-(Vec3 a, Vec3 b) {
  return Vec3{a.x - b.x, a.y - b.y, a.z - b.z};
}
SPH_HD Vec3 operator-(Vec3 a) {
  return Vec3{-a.x, -a.y, -a.z};
}
SPH_HD Vec3 operator*(Vec3 a, float s) {
  return Vec3{a.x * s, a.y * s, a.z * s};
}
SPH_HD Vec3 operator*(float s, Vec3 a) {
  return a * s;
}
SPH_HD Vec3 operator/(Vec3 a, float s) {
  return a * (1.0f / s);
}
SPH_HD Vec3& operator+=(Vec3& a, Vec3 b) {
  a = a + b;
  return a;
}
SPH_HD Vec3& operator-=(Vec3& a, Vec3 b) {
  a = a - b;
  return a;
}
SPH_HD float dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
SPH_HD float lengthSquared(Vec3 a) {
  return dot(a, a);
}
SPH_HD float length(Vec3 a) {
  return realSqrt(dot(a, a));
}
SPH_HD bool isFinite(float v) {
#if defined(__CUDA_ARCH__)
  return isfinite(v);
#else
  return std::isfinite(v);
#endif
}
SPH_HD bool isFinite(Vec3 a) {
  return isFinite(a.x) && isFinite(a.y) && isFinite(a.z);
}

}  // namespace sph
