// Stage: the fluid just downstream of each emitter (sim/emitters.hpp) moves at the emitter's
// velocity, as a piston would push it, so that the flow ahead cannot push it back through the
// opening. Before integrate: sets velocity and clears acceleration there.
#pragma once

#include <cstdint>

#include "fluid/particles.hpp"

namespace sph::fluid {

constexpr std::uint32_t kInflowSlots = 8;

// The region an emitter drives: points whose distance along `normal` from `origin` is in
// [behind, depth) and whose foot on the emitter's plane lies in its disc (radius > 0) or in
// its parallelogram origin + a e1 + b e2, a, b in [0, 1], with a = dual1·r, b = dual2·r.
struct InflowZone {
  Vec3 origin;
  Vec3 normal;  // unit, the direction of flow
  Vec3 dual1, dual2;
  float radius;  // 0: a parallelogram
  float behind, depth;
  float speed;
};

struct InflowZones {
  std::uint32_t count = 0;
  InflowZone zone[kInflowSlots];
};

SPH_HD bool insideInflow(const InflowZone& z, Vec3 x) {
  const Vec3 r = x - z.origin;
  const float along = dot(r, z.normal);
  if (!(along >= z.behind && along < z.depth)) return false;
  if (z.radius > 0.0f) return dot(r, r) - along * along <= z.radius * z.radius;
  const float a = dot(r, z.dual1);
  const float b = dot(r, z.dual2);
  return a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f;
}

template <class B>
void driveInflow(FluidParticles<B>& fluid, const InflowZones& zones) {
  if (zones.count == 0) return;
  const Vec4* position = fluid.position.data();
  Vec4* velocity = fluid.velocity.data();
  Vec4* acceleration = fluid.acceleration.data();
  const InflowZones z = zones;
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 x = xyz(position[i]);
        for (std::uint32_t k = 0; k < z.count; ++k) {
          if (!insideInflow(z.zone[k], x)) continue;
          velocity[i] = makeVec4(z.zone[k].normal * z.zone[k].speed, velocity[i].w);
          acceleration[i] = makeVec4(Vec3{0.0f, 0.0f, 0.0f}, acceleration[i].w);
          return;
        }
      });
}

}  // namespace sph::fluid
