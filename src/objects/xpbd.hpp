// A deformable's springs as XPBD distance constraints (Macklin, Müller, Chentanez, "XPBD:
// Position-Based Simulation of Compliant Constrained Dynamics", 2016), stepped as in Macklin et
// al., "Small Steps in Physics Simulation" (2019): many substeps of one constraint iteration
// each. A constraint of compliance α = 1/k holds a static load as a spring of stiffness k does,
// but no stiffness bounds the substep.
#pragma once

#include <cstdint>
#include <vector>

#include "objects/math3d.hpp"
#include "objects/springs.hpp"

namespace sph::objects {

// Bending at a particle `middle` between two nearest neighbours a and b nearly opposite it:
// the triangle bending constraint of Kelager, Niebe, Erleben, "A Triangle Bending Constraint
// Model for Position-Based Dynamics" (2010), C = |x_m − c| − h0, c the centroid of the three.
// Unlike a distance constraint between a and b, it resists a straight line's bending at first
// order. It spans the springs a–middle and middle–b and goes when either breaks, so that a tear
// does not stay stitched.
struct BendingTriple {
  std::uint32_t a, middle, b;  // particle indices, a < b
  double restOffset;           // h0 = |x_m − c| at rest, m
  std::uint32_t spanned[2];    // spring indices
};

struct XpbdConstraints {
  int substeps = 1;               // per engine step
  double bendingStiffness = 0.0;  // N/m; 0: no bending triples
  std::vector<BendingTriple> bending;
  std::vector<std::uint8_t> bendingBroken;
  std::vector<double> inverseMass;  // per particle of the network, 1/kg; 0: pinned
  // The springs in the order they are projected: by colour, no two springs of a colour sharing
  // a particle, so that each projection need not wait for the one before it.
  std::vector<std::uint32_t> springOrder;
  std::vector<DVec3> direction;  // scratch, per spring: its unit vector a → b when projected
  std::vector<DVec3> previous;   // scratch: positions at the start of the substep
};

// The constraints of a network whose stiffness and damping are set: bending triples (below) when
// `bendingStiffness` > 0, and each particle's inverse mass, 0 where pinned.
XpbdConstraints makeXpbdConstraints(const SpringNetwork& net, const std::vector<DVec3>& position,
                                    const std::vector<float>& mass,
                                    const std::vector<std::uint8_t>& pinned, double shell,
                                    double bendingStiffness, int substeps);

// Breaks the bending triples that span a broken spring.
void breakBendingAcrossTears(const SpringNetwork& net, XpbdConstraints& xpbd);

// The bending triples of the network: for each particle, every two of its neighbours closer
// than `shell` that lie on opposite sides within 30° of a straight line. Ordered by middle.
std::vector<BendingTriple> buildBendingTriples(const SpringNetwork& net,
                                               const std::vector<DVec3>& position, double shell);

// One substep of the network's particles, in three parts so that the contacts between objects
// can be projected after every network's own constraints (ObjectWorld::substep):
// predict with `force` (N, per particle index) and gravity; project every intact constraint
// once in their fixed order; derive the velocities, damp along each constraint, then break what
// is overstretched (breakOverstretched). Pinned particles have infinite mass and never move.
void xpbdPredict(const SpringNetwork& net, XpbdConstraints& xpbd, double h, DVec3 gravity,
                 const std::vector<DVec3>& force, std::vector<DVec3>& position,
                 std::vector<DVec3>& velocity);
void xpbdProject(const SpringNetwork& net, XpbdConstraints& xpbd, double h,
                 std::vector<DVec3>& position);
void xpbdFinish(SpringNetwork& net, XpbdConstraints& xpbd, double h,
                const std::vector<DVec3>& position, std::vector<DVec3>& velocity,
                std::vector<std::uint8_t>& cut);

}  // namespace sph::objects
