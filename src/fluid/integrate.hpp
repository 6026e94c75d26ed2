// Stage: symplectic Euler, v += dt a then x += dt v; then the damped box of the 2021 CUDA SPH
// tutorial, or the clamp policy, keeps particles in the domain. Returns how many the clamp put
// back.
#pragma once

#include "fluid/parameters.hpp"
#include "fluid/particles.hpp"

namespace sph::fluid {

namespace detail {

// The 2021 CUDA SPH tutorial's box: a particle past a face is put back on it, its normal
// velocity reversed and scaled by the damping.
SPH_HD void reflect(float& x, float& v, float lo, float hi, float damping) {
  if (x < lo) {
    x = lo;
    if (v < 0.0f) v = -v * damping;
  } else if (x > hi) {
    x = hi;
    if (v > 0.0f) v = -v * damping;
  }
}

// The scene's "clamp" policy: a particle past a face is put back on it and stops moving out.
SPH_HD bool clamp(float& x, float& v, float lo, float hi) {
  if (x < lo) {
    x = lo;
    if (v < 0.0f) v = 0.0f;
    return true;
  }
  if (x > hi) {
    x = hi;
    if (v > 0.0f) v = 0.0f;
    return true;
  }
  return false;
}

}  // namespace detail

template <class B>
std::size_t integrate(FluidParticles<B>& fluid, float dt, const DomainParameters& domain) {
  Vec4* position = fluid.position.data();
  Vec4* velocity = fluid.velocity.data();
  const Vec4* acceleration = fluid.acceleration.data();
  const DomainParameters d = domain;

  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        Vec3 v = xyz(velocity[i]) + xyz(acceleration[i]) * dt;
        Vec3 x = wrapIntoDomain(d.periodic, xyz(position[i]) + v * dt);
        if (d.dampedBox) {
          detail::reflect(x.x, v.x, d.min.x, d.max.x, d.damping);
          detail::reflect(x.y, v.y, d.min.y, d.max.y, d.damping);
          detail::reflect(x.z, v.z, d.min.z, d.max.z, d.damping);
        }
        bool clamped = false;
        if (d.clampOutside && !d.dampedBox) {
          clamped = detail::clamp(x.x, v.x, d.min.x, d.max.x);
          clamped = detail::clamp(x.y, v.y, d.min.y, d.max.y) || clamped;
          clamped = detail::clamp(x.z, v.z, d.min.z, d.max.z) || clamped;
        }
        velocity[i] = makeVec4(v, clamped ? 1.0f : 0.0f);  // w: clamped this step
        position[i] = makeVec4(x);
      });
  if (!d.clampOutside || d.dampedBox) return 0;
  const std::uint32_t* id = fluid.id.data();
  // A distributed run's ghosts are counted by their owners.
  return B::reduce(
      fluid.count, std::size_t{0},
      SPH_LAMBDA(std::size_t i) {
        return isGhost(id[i]) ? std::size_t{0} : std::size_t(velocity[i].w);
      },
      SPH_LAMBDA(std::size_t a, std::size_t b) { return a + b; });
}

}  // namespace sph::fluid
