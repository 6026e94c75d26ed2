// What lets a formula be written once for one float (the GPU, and scalar CPU code) and for a
// batch of floats (the CPU's SIMD passes, std::experimental::simd): a comparison gives a bool
// or a mask, select() picks by it, and realSqrt() takes either. Formulas use no branches on
// values, so both compile from the same source.
#pragma once

#include "sph/core/vec.hpp"

#if !defined(__CUDACC__)
#include <experimental/simd>
#endif

namespace sph {

SPH_HD float select(bool condition, float ifTrue, float ifFalse) {
  return condition ? ifTrue : ifFalse;
}
SPH_HD double select(bool condition, double ifTrue, double ifFalse) {
  return condition ? ifTrue : ifFalse;
}

// What a sum over one neighbour at a time adds up to is already the particle's: summing the
// lanes is for batches.
SPH_HD float sumLanes(float v) {
  return v;
}
SPH_HD Vec3 sumLanes(Vec3 v) {
  return v;
}

// A vector in every lane: V is Vec3 (itself) or BatchVec3.
template <class V>
SPH_HD V spread(Vec3 v) {
  return v;
}

#if !defined(__CUDACC__)
namespace stdx = std::experimental;

// The CPU's batch: as many floats as the build's vector registers hold (8 with AVX2).
using FloatBatch = stdx::native_simd<float>;

// Always inlined: a few instructions each, inside the neighbour loops, where GCC otherwise
// keeps some of them as calls (select was 6 % of a step).
#define SPH_BATCH_INLINE inline __attribute__((always_inline))
// The same for a lambda, written after its parameters.
#define SPH_BATCH_INLINE_LAMBDA __attribute__((always_inline))

template <class T, class Abi>
SPH_BATCH_INLINE stdx::simd<T, Abi> select(const stdx::simd_mask<T, Abi>& condition,
                                           stdx::simd<T, Abi> ifTrue,
                                           const stdx::simd<T, Abi>& ifFalse) {
  stdx::where(!condition, ifTrue) = ifFalse;
  return ifTrue;
}

template <class Abi>
SPH_BATCH_INLINE stdx::simd<float, Abi> realSqrt(const stdx::simd<float, Abi>& v) {
  return stdx::sqrt(v);
}

// A Vec3 of batches: lane k of x, y, z is one neighbour's vector.
struct BatchVec3 {
  FloatBatch x, y, z;
};

SPH_BATCH_INLINE BatchVec3 broadcast(Vec3 v) {
  return {FloatBatch(v.x), FloatBatch(v.y), FloatBatch(v.z)};
}
SPH_BATCH_INLINE BatchVec3 operator+(const BatchVec3& a, const BatchVec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
SPH_BATCH_INLINE BatchVec3 operator-(const BatchVec3& a, const BatchVec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
SPH_BATCH_INLINE BatchVec3 operator-(const BatchVec3& a) {
  return {-a.x, -a.y, -a.z};
}
SPH_BATCH_INLINE BatchVec3 operator*(const BatchVec3& a, const FloatBatch& s) {
  return {a.x * s, a.y * s, a.z * s};
}
SPH_BATCH_INLINE BatchVec3& operator+=(BatchVec3& a, const BatchVec3& b) {
  a.x += b.x;
  a.y += b.y;
  a.z += b.z;
  return a;
}
SPH_BATCH_INLINE FloatBatch dot(const BatchVec3& a, const BatchVec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
// The sum over the lanes: what the batch of neighbours adds to one particle.
SPH_BATCH_INLINE Vec3 sumLanes(const BatchVec3& a) {
  return {stdx::reduce(a.x), stdx::reduce(a.y), stdx::reduce(a.z)};
}
SPH_BATCH_INLINE float sumLanes(const FloatBatch& a) {
  return stdx::reduce(a);
}
template <>
SPH_BATCH_INLINE BatchVec3 spread<BatchVec3>(Vec3 v) {
  return broadcast(v);
}
#endif

}  // namespace sph
