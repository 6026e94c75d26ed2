// Contact between two particles by the discrete element method (Meteer 2011, §7.4, eqs. 13-16,
// Algorithm 3; Harada 2007): a linear spring against overlap, a dashpot on the relative
// velocity and a shear term on its tangential part. Used between fluid and object particles
// (the interaction) and between the particles of different objects (the object engine).
//
// Conventions: `offset` is x_a - x_b, `relativeVelocity` is v_b - v_a. The result is the force
// on particle a; particle b receives its exact negation, so every pair conserves momentum.
#pragma once

#include <cmath>

#include "sph/core/vec.hpp"

namespace sph {

struct ContactCoefficients {
  float spring;   // k_spring, N/m
  float damping;  // k_damping, N·s/m
  float shear;    // k_shear, N·s/m
};

// Meteer 2011, §8.2, figure 7: the spring term is multiplied by a distance function that grows
// exponentially as a fluid particle nears the object particle, so that a particle heading into
// a hole between object particles is sent back before it gets through. The function is
// φ(q) = exp(β (1 - q)) for q = |r| / R in [0, 1] (R: contact distance through the influence
// sphere): 1 at the rim of the influence sphere, e^β at the centre. The GPU reads it from a
// small table by linear interpolation (constant memory, as the paper suggests); the CPU reads
// the same table so both give the same numbers.
struct DistanceFunctionTable {
  static constexpr int kSize = 64;  // intervals; kSize + 1 samples
  float value[kSize + 1];

  static DistanceFunctionTable make(double exponent);

  SPH_HD float operator()(float q) const {
    if (q <= 0.0f) return value[0];
    if (q >= 1.0f) return value[kSize];
    const float x = q * float(kSize);
    const int k = int(x);
    const float t = x - float(k);
    return value[k] + t * (value[k + 1] - value[k]);
  }
};

// Exact φ(q) = exp(β (1 - q)), what the table samples.
inline double distanceFunction(double exponent, double q) {
  return std::exp(exponent * (1.0 - q));
}

// The largest φ, e^β, at the centre of the influence sphere: where the contact is stiffest.
inline double distanceFunctionPeak(double exponent) {
  return distanceFunction(exponent, 0.0);
}

inline DistanceFunctionTable DistanceFunctionTable::make(double exponent) {
  DistanceFunctionTable table{};
  for (int k = 0; k <= kSize; ++k)
    table.value[k] = static_cast<float>(distanceFunction(exponent, double(k) / kSize));
  return table;
}

// Meteer 2011, eq. 16: the part of v perpendicular to the unit normal n.
SPH_HD Vec3 tangentialPart(Vec3 v, Vec3 n) {
  return v - n * dot(v, n);
}

// Meteer 2011, eqs. 13-15 for particles a and b whose spheres (radii summing to `reach`) overlap.
// `springScale` multiplies the spring term (the distance function, or 1); `damped` turns the
// dashpot off where the object is cut (Meteer 2011, §8.2, the cut-aware variant), so blood may
// leave through a tear while an intact wall still damps it.
// Returns zero when the spheres do not touch or the particles coincide.
SPH_HD Vec3 demContactForce(const ContactCoefficients& k, Vec3 offset, Vec3 relativeVelocity,
                            float reach, float springScale, bool damped) {
  const float r2 = lengthSquared(offset);
  if (r2 >= reach * reach || r2 <= 0.0f) return Vec3{0.0f, 0.0f, 0.0f};
  const float r = realSqrt(r2);
  const Vec3 n = offset / r;  // from b to a: the spring pushes a this way
  Vec3 force = n * (k.spring * springScale * (reach - r));
  if (damped) force += relativeVelocity * k.damping;
  force += tangentialPart(relativeVelocity, n) * k.shear;
  return force;
}

// A spring with a dashpot along it (the object engine's deformables): the tension, positive
// when stretched, k (l − l0) + c dl/dt. Each end is pulled toward the other by it.
template <class Real>
SPH_HD Real springTension(Real stiffness, Real damping, Real length, Real restLength,
                          Real stretchRate) {
  return stiffness * (length - restLength) + damping * stretchRate;
}

}  // namespace sph
