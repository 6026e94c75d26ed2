// Periodic boundaries: along a periodic axis the domain's two faces are one, so what leaves
// through one comes back through the other, and a particle near one face has neighbours
// near the other. Positions stay inside [lo, hi); a pair's separation is taken to the nearest
// image (the minimum-image convention), which is unique while the period is at least twice
// the kernel's support.
#pragma once

#include <cmath>
#include <cstdint>

#include "sph/core/select.hpp"
#include "sph/core/vec.hpp"

namespace sph {

struct Periodicity {
  std::uint32_t axes = 0;  // bit a: axis a (x 1, y 2, z 4) is periodic
  Vec3 lo{0, 0, 0};        // the domain's faces along the periodic axes
  Vec3 hi{0, 0, 0};
  Vec3 length{0, 0, 0};  // hi - lo along a periodic axis; 0 along the others
  Vec3 half{1e30f, 1e30f,
            1e30f};    // length / 2 along a periodic axis; beyond reach along the others
  float reach = 0.0f;  // the farthest a neighbour can be: the kernel's support
};

SPH_HD bool isPeriodic(const Periodicity& p, int axis) {
  return (p.axes >> axis) & 1u;
}

inline Periodicity makePeriodicity(std::uint32_t axes, Vec3 lo, Vec3 hi, float reach) {
  Periodicity p;
  p.axes = axes;
  p.reach = reach;
  const float los[3] = {lo.x, lo.y, lo.z}, his[3] = {hi.x, hi.y, hi.z};
  float* plo[3] = {&p.lo.x, &p.lo.y, &p.lo.z};
  float* phi[3] = {&p.hi.x, &p.hi.y, &p.hi.z};
  float* length[3] = {&p.length.x, &p.length.y, &p.length.z};
  float* half[3] = {&p.half.x, &p.half.y, &p.half.z};
  for (int a = 0; a < 3; ++a) {
    if (!isPeriodic(p, a)) continue;
    *plo[a] = los[a];
    *phi[a] = his[a];
    *length[a] = his[a] - los[a];
    *half[a] = 0.5f * (his[a] - los[a]);
  }
  return p;
}

// Whether a neighbour of x within reach may lie across a periodic face: only then does a
// separation need wrapping, so the passes test this once a particle, not once a pair.
SPH_HD_INLINE bool nearSeam(const Periodicity& p, Vec3 x) {
  if (p.axes == 0) return false;
  const auto near = [&](int axis, float v, float lo, float hi) {
    return isPeriodic(p, axis) && (v - lo < p.reach || hi - v < p.reach);
  };
  return near(0, x.x, p.lo.x, p.hi.x) || near(1, x.y, p.lo.y, p.hi.y) ||
         near(2, x.z, p.lo.z, p.hi.z);
}

// One component of a separation, to its nearest image: F is a float or a SIMD batch.
template <class F>
SPH_HD_INLINE F nearestImage(F d, float length, float half) {
  return select(d > F(half), d - F(length), select(d < F(-half), d + F(length), d));
}

// A separation x_i - x_j of two positions inside the domain, to its nearest image. V is Vec3
// or a BatchVec3.
template <class V>
SPH_HD_INLINE V minimumImage(const Periodicity& p, V d) {
  d.x = nearestImage(d.x, p.length.x, p.half.x);
  d.y = nearestImage(d.y, p.length.y, p.half.y);
  d.z = nearestImage(d.z, p.length.z, p.half.z);
  return d;
}

// x_i - x_j, to its nearest image when x_i is near a seam (`seam`, from nearSeam).
template <class V>
SPH_HD_INLINE V separation(const Periodicity& p, bool seam, const V& xi, const V& xj) {
  const V d = xi - xj;
  return seam ? minimumImage(p, d) : d;
}

// x back inside [lo, hi) along the periodic axes, after a step that took it through a face
// (never more than a period in one step).
SPH_HD Vec3 wrapIntoDomain(const Periodicity& p, Vec3 x) {
  const auto wrap = [](float v, float lo, float hi, float length) {
    if (v < lo) {
      v += length;
    } else if (v >= hi) {
      v -= length;
    }
    // Rounding can leave a particle that was a hair from the face just outside: it is at it.
    return (v < lo || v >= hi) ? lo : v;
  };
  if (isPeriodic(p, 0)) x.x = wrap(x.x, p.lo.x, p.hi.x, p.length.x);
  if (isPeriodic(p, 1)) x.y = wrap(x.y, p.lo.y, p.hi.y, p.length.y);
  if (isPeriodic(p, 2)) x.z = wrap(x.z, p.lo.z, p.hi.z, p.length.z);
  return x;
}

// v moved by whole periods into [lo, lo + length), however many periods away it lies (an
// object kept whole may reach far past a face). T is float or double; on the host.
template <class T>
T intoPeriod(T v, T lo, T length) {
  const T w = v - length * std::floor((v - lo) / length);
  return w < lo + length ? w : lo;  // rounding can land a hair past the upper face
}

// Calls visit(shift) with shift[a] in {-1, 0, 1} periods along axis a: first no shift, then each
// shift along a periodic axis (or, near an edge or a corner, several) that brings the point
// `at` within `reach` of the domain [lo, hi) from beyond the opposite face. The period must
// exceed twice the reach, so that each axis has at most one. On the host.
template <class T, class Visit>
void forEachPeriodicImage(const bool periodic[3], const T at[3], const T lo[3], const T hi[3],
                          T reach, Visit&& visit) {
  int shifts[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  int count[3] = {1, 1, 1};
  for (int a = 0; a < 3; ++a) {
    if (!periodic[a]) continue;
    if (at[a] < lo[a] + reach)
      shifts[a][count[a]++] = 1;
    else if (at[a] > hi[a] - reach)
      shifts[a][count[a]++] = -1;
  }
  for (int i = 0; i < count[0]; ++i)
    for (int j = 0; j < count[1]; ++j)
      for (int k = 0; k < count[2]; ++k) {
        const int shift[3] = {shifts[0][i], shifts[1][j], shifts[2][k]};
        visit(shift);
      }
}

}  // namespace sph
