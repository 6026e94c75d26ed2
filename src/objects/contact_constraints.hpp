// Contact between an XPBD deformable's particles and the particles they meet (another XPBD
// deformable's, a kinematic object's, a pinned one's, the walls') as constraints: the discrete
// element contact of object_contacts.hpp — the same spring, dashpot and shear coefficients —
// integrated implicitly, so that no contact stiffness bounds the engine's substep.
//
// The spring becomes a compliant non-penetration constraint C = |x_a − x_b| − (r_a + r_b) ≥ 0 of
// compliance 1/k_spring (Macklin, Müller, Chentanez, "XPBD", 2016): it holds a static load at
// the overlap the spring would. The dashpot and the shear act after the positions are solved,
// as an implicit velocity pass on each touching pair (as xpbd.cpp damps its springs): the
// relative velocity's normal part decays at the dashpot's rate, its tangential part at the
// dashpot's plus the shear's.
#pragma once

#include <cstdint>
#include <vector>

#include "objects/object_contacts.hpp"

namespace sph::objects {

// A touching pair: particle a (Projected) against particle b of another object, or against the
// static particle b when `againstStatic`.
struct ConstraintContact {
  std::uint32_t a, b;
  bool againstStatic;
};

struct ContactConstraints {
  ContactSearch search;
  // The fluid's periodic axes: each pair is solved along its nearest image.
  PeriodicSpace space;
  // The pairs within reach plus a margin at the engine step's start (findContactCandidates), and
  // of them those touching now (selectTouching), in a fixed order.
  std::vector<ConstraintContact> candidates, touching;
};

// The walls as the constraints meet them: fixed particles of one radius.
struct StaticParticles {
  const std::vector<DVec3>& position;
  float radius;
  const PointGrid& grid;
};

// Lists the pairs closer than their radii plus `margin`, at the current positions, of a
// Projected particle with a particle of another object that is not Pushed (Pushed pairs stay
// forces), or with a static particle. Each pair once: from the lower index when both are
// Projected. Searched once an engine step, with a margin as far as two particles can close in
// it, the pairs serve every substep.
void findContactCandidates(const ContactParticles& p, float maxRadius, double margin,
                           const StaticParticles& statics, ContactConstraints& contacts);

// Keeps in `touching` the candidates that overlap at the current positions.
void selectTouching(const std::vector<DVec3>& position, const std::vector<float>& radius,
                    const StaticParticles& statics, ContactConstraints& contacts);

// Projects each listed contact once, in order, pushing the pair apart along the line between
// them by their inverse masses (0 where fixed), and adds the impulse of each correction to
// `impulse` by object (N·s: m Δx / h), equal and opposite.
void projectContactConstraints(const ContactCoefficients& k, double h,
                               const std::vector<double>& inverseMass,
                               const std::vector<float>& radius,
                               const std::vector<std::int32_t>& object,
                               const StaticParticles& statics, const ContactConstraints& contacts,
                               std::vector<DVec3>& position, std::vector<DVec3>& impulse);

// The implicit dashpot and shear on each listed contact, after the positions are solved and the
// velocities derived from them; adds the impulses to `impulse` by object.
void dampContactConstraints(const ContactCoefficients& k, double h,
                            const std::vector<double>& inverseMass,
                            const std::vector<std::int32_t>& object, const StaticParticles& statics,
                            const ContactConstraints& contacts, const std::vector<DVec3>& position,
                            std::vector<DVec3>& velocity, std::vector<DVec3>& impulse);

}  // namespace sph::objects
