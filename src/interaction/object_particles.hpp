// The objects' surface particles as the fluid sees them (Meteer 2011, §7.2), in the memory of
// backend B, sorted by the cells of their own grid, and the numbers the contact pass reads.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sph/core/contact.hpp"
#include "sph/core/grid.hpp"
#include "sph/core/vec.hpp"

namespace sph::interaction {

// Passed by value to the per-particle code (constant memory on the GPU, Meteer 2011, §8.2).
struct InteractionParameters {
  ContactCoefficients contact;
  DistanceFunctionTable distance;
  float fluidRadius;      // half the fluid spacing, m
  float influenceRatio;   // influence sphere radius / object particle radius
  float fluidMass;        // kg
  float maxAcceleration;  // m/s², clamp on a fluid particle's total acceleration (§8.3)
  bool cutAwareDamping;
  // The objects' surface particles are boundary particles of the fluid's density and pressure
  // solve (Akinci et al. 2012, with the incompressible solver) rather than the contact forces'
  // partners; the contact pass then only tracks containment.
  bool boundary;
};

// The largest distance at which a fluid particle and an object particle of radius
// `objectRadius` touch through the influence sphere (Meteer 2011, §8.2, figure 6).
SPH_HD float contactReach(const InteractionParameters& p, float objectRadius) {
  return p.fluidRadius + p.influenceRatio * objectRadius;
}

// What rides in the w of an object particle's vectors, packed so that a GPU loads each as one
// 16-byte word: the radius (position), whether it is torn (velocity), its object (normal).
SPH_HD Vec4 packPosition(Vec3 x, float radius) {
  return makeVec4(x, radius);
}
SPH_HD float radiusOf(const Vec4& position) {
  return position.w;
}
SPH_HD Vec4 packVelocity(Vec3 v, bool cut) {
  return makeVec4(v, cut ? 1.0f : 0.0f);
}
SPH_HD bool isCut(const Vec4& velocity) {
  return velocity.w != 0.0f;
}
SPH_HD Vec4 packNormal(Vec3 n, std::int32_t object) {
  return makeVec4(n, float(object));  // exact for ids below 2²⁴
}
SPH_HD std::int32_t objectOf(const Vec4& normal) {
  return std::int32_t(normal.w);
}

// Written when the engine publishes (prepareObjectParticles), read by computeContacts.
template <class B>
struct ObjectParticles {
  template <class T>
  using Buffer = typename B::template Buffer<T>;
  std::size_t count = 0;
  GridSpec grid;                    // cell edge: the largest contact reach
  Buffer<std::uint32_t> cellStart;  // cellCount + 1
  Buffer<Vec4> position;            // xyz; w: radius
  Buffer<Vec4> velocity;            // xyz; w: 1 where torn (cut), else 0
  Buffer<Vec4> normal;              // xyz: outward normal; w: object id
  Buffer<std::uint32_t> handle;     // the engine's particle index
  // Per object id: the lower and upper corners of the box around its intact surface
  // particles, widened by the contact reach (2 per object).
  Buffer<Vec4> bounds;
  // computed by computeContacts (count): the fluid's force on each object particle, N
  Buffer<Vec4> force;  // xyz; w: fluid particles in contact
};

// Leak tracking (an intact vessel leaks nothing), by fluid particle id.
template <class B>
struct ContainmentState {
  template <class T>
  using Buffer = typename B::template Buffer<T>;
  // Object that held the particle at the start, or -1.
  Buffer<std::int32_t> containerById;
  // 1 while inside its container; updated whenever the particle is near the container's
  // particles (it cannot cross the wall without passing them).
  Buffer<std::uint32_t> insideById;
  // Where the particle first left its container: xyz; w = 1 once it has.
  Buffer<Vec4> firstExitById;
};

}  // namespace sph::interaction
