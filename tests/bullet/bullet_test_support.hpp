// What the Bullet tests share: an engine's settings from the scene it joins, and whether the
// run is under the sanitizers (then short runs that must run clean).
#pragma once

#include "../sim/backends.hpp"
#include "sph/bullet_engine.hpp"
#include "sph/scene.hpp"

namespace sph::testing {

// The bodies' particles on the fluid's lattice, under the scene's gravity.
inline BulletEngine::Settings bulletSettings(const Scene& scene) {
  BulletEngine::Settings s;
  s.spacing = scene.fluid.spacing;
  s.gravity = scene.gravity;
  return s;
}

}  // namespace sph::testing
