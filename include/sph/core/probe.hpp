// What a probe reads of the fluid at a point (scene "probes"): kernel interpolation with
// Shepard's normalisation, as DualSPHysics's gauges take it,
//   A(x) = Σ_j V_j A_j W(x - x_j) / Σ_j V_j W(x - x_j),   V_j = m_j / ρ_j,
// over the fluid particles alone. The denominator is how much of the kernel's support around x
// the fluid fills: about 1 inside it, about 1/2 on a flat free surface, 0 in the air; a level
// gauge puts the free surface where it falls through 1/2.
#pragma once

#include "sph/core/vec.hpp"

namespace sph {

struct PointSums {
  float filled = 0.0f;    // Σ V_j W
  float pressure = 0.0f;  // Σ V_j W p_j
  float density = 0.0f;   // Σ V_j W ρ_j
  Vec3 velocity{0.0f, 0.0f, 0.0f};
};

// One fluid particle j: V_j W(x - x_j) = volumeW.
SPH_HD void addToPointSums(PointSums& sums, float volumeW, float pressure, float density,
                           Vec3 velocity) {
  sums.filled += volumeW;
  sums.pressure += volumeW * pressure;
  sums.density += volumeW * density;
  sums.velocity += velocity * volumeW;
}

// Below this share of a filled support a point is in the air: its values are not read.
constexpr float kSmallestFilledShare = 0.1f;

struct PointValues {
  bool wet = false;  // the fluid fills at least kSmallestFilledShare of the support
  float pressure = 0.0f;
  float density = 0.0f;
  Vec3 velocity{0.0f, 0.0f, 0.0f};
};

SPH_HD PointValues pointValues(const PointSums& sums) {
  PointValues out;
  out.wet = sums.filled >= kSmallestFilledShare;
  if (!out.wet) return out;
  const float inverse = 1.0f / sums.filled;
  out.pressure = sums.pressure * inverse;
  out.density = sums.density * inverse;
  out.velocity = sums.velocity * inverse;
  return out;
}

// The free surface along a gauge's line: `filled[k]` sampled at k·step from its start, k < n.
// Returns the distance from the start to the last place, going up the line, where the filled
// share falls through 1/2 (linear between samples): the depth of water over the start of a
// gauge standing on the floor. 0 when no sample is filled to 1/2; the whole length when the
// last one is.
inline float levelAlong(const float* filled, int n, float step) {
  for (int k = n - 1; k >= 0; --k) {
    if (filled[k] < 0.5f) continue;
    if (k == n - 1) return float(k) * step;
    const float above = filled[k + 1];
    const float t = (filled[k] - 0.5f) / (filled[k] - above);
    return (float(k) + t) * step;
  }
  return 0.0f;
}

}  // namespace sph
