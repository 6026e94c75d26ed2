// Contact between particles of different objects by the discrete element method
// (core/contact.hpp, Meteer 2011, eqs. 13-15), found through a uniform grid rebuilt every substep.
#pragma once

#include <cstdint>
#include <vector>

#include "objects/math3d.hpp"
#include "objects/periodic_space.hpp"
#include "objects/point_grid.hpp"
#include "sph/core/contact.hpp"

namespace sph::objects {

// How a particle meets the particles of other objects.
enum class ContactRole : std::uint8_t {
  Fixed,      // kinematic or pinned: moves only as prescribed
  Pushed,     // of a rigid body or a spring network: contacts are forces on it (here)
  Projected,  // of an XPBD deformable: contacts are constraints on its position
              // (contact_constraints.hpp), unless the other particle is Pushed
};

struct ContactParticles {
  const std::vector<DVec3>& position;
  const std::vector<DVec3>& velocity;
  const std::vector<float>& radius;
  const std::vector<std::int32_t>& object;
  const std::vector<ContactRole>& role;
  // Only particles in here touch anything (WorldSettings::regionMin, regionMax).
  DVec3 regionMin, regionMax;
  // The fluid's periodic axes: pairs meet across a periodic face (periodic_space.hpp).
  const PeriodicSpace& space;
};

// What the search between objects keeps from one substep to the next, to allocate nothing.
struct ContactSearch {
  PointGrid grid;
  // By particle, its position moved into the domain along the periodic axes: what the grid
  // holds and the search starts from. Empty without periodic axes (the positions themselves).
  std::vector<DVec3> wrapped;
  std::vector<std::uint8_t> near;     // by particle: within reach of another object's box
  std::vector<DVec3> boxMin, boxMax;  // by object
};

// Marks in `search.near` the particles in the region within `reach` of the bounding box of an
// object other than their own (of the wrapped positions, from any image): the only ones that can
// touch another object. Fills `search.wrapped` first.
void markNearOtherObjects(const ContactParticles& p, double reach, ContactSearch& search);

// Adds to `force` the contact force of every overlapping pair of particles of different objects
// of which at least one is Pushed: equal and opposite, full spring, damped. Returns the number
// of touching pairs.
std::size_t addContactForces(const ContactCoefficients& coefficients, const ContactParticles& p,
                             float maxRadius, ContactSearch& search, std::vector<DVec3>& force);

// Adds to `force` the contact force of the static particles (in `staticGrid`, all of radius
// `staticRadius`, inside the domain) on every Pushed particle touching one. Returns the number
// of touching pairs.
std::size_t addStaticContactForces(const ContactCoefficients& coefficients,
                                   const ContactParticles& p, const std::vector<DVec3>& statics,
                                   float staticRadius, const PointGrid& staticGrid,
                                   std::vector<DVec3>& force);

// The positions a search reads: `search.wrapped` with periodic axes, else p.position.
const std::vector<DVec3>& searchPositions(const ContactParticles& p, const ContactSearch& search);

}  // namespace sph::objects
