// Contact between particles of different objects by the discrete element method
// (core/contact.hpp, Meteer 2011, eqs. 13-15), found through a uniform grid rebuilt every substep.
#pragma once

#include <cstdint>
#include <vector>

#include "objects/math3d.hpp"
#include "objects/point_grid.hpp"
#include "sph/core/contact.hpp"

namespace sph::objects {

struct ContactParticles {
  const std::vector<DVec3>& position;
  const std::vector<DVec3>& velocity;
  const std::vector<float>& radius;
  const std::vector<std::int32_t>& object;
  const std::vector<std::uint8_t>& movable;  // 0: kinematic or pinned
  // Only particles in here touch anything (WorldSettings::regionMin, regionMax).
  DVec3 regionMin, regionMax;
};

// What the search between objects keeps from one substep to the next, to allocate nothing.
struct ContactSearch {
  PointGrid grid;
  std::vector<std::uint8_t> near;     // by particle: within reach of another object's box
  std::vector<DVec3> boxMin, boxMax;  // by object
};

// Adds to `force` the contact force of every overlapping pair of particles of different objects
// of which at least one can move: equal and opposite, full spring, damped. Returns the number
// of touching pairs.
std::size_t addContactForces(const ContactCoefficients& coefficients, const ContactParticles& p,
                             float maxRadius, ContactSearch& search, std::vector<DVec3>& force);

// Adds to `force` the contact force of the static particles (in `staticGrid`, all of radius
// `staticRadius`) on every movable particle touching one. Returns the number of touching pairs.
std::size_t addStaticContactForces(const ContactCoefficients& coefficients,
                                   const ContactParticles& p, const std::vector<DVec3>& statics,
                                   float staticRadius, const PointGrid& staticGrid,
                                   std::vector<DVec3>& force);

}  // namespace sph::objects
