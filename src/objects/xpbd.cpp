#include "objects/xpbd.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "sph/core/constants.hpp"

namespace sph::objects {

namespace {

// Neighbours within 30° of opposite directions make a line that can fold at its middle.
const double kStraightCosine = -std::cos(kPi / 6.0);

// The index of the spring joining a and b (a < b), or springs.size() if none.
std::size_t findSpring(const std::vector<Spring>& springs, std::uint32_t a, std::uint32_t b) {
  const auto it = std::lower_bound(
      springs.begin(), springs.end(), Spring{a, b, 0.0},
      [](const Spring& s, const Spring& key) { return s.a != key.a ? s.a < key.a : s.b < key.b; });
  return it != springs.end() && it->a == a && it->b == b ? std::size_t(it - springs.begin())
                                                         : springs.size();
}

// A constraint on up to three particles, as its value and gradients at the current positions.
struct Linearised {
  std::uint32_t particle[3];
  DVec3 gradient[3];
  double inverseMass[3];
  int count = 0;
  double value = 0.0;
  bool valid = false;

  // Σ w_i |∇_i C|²: how much the constraint moves per unit of multiplier.
  double weight() const {
    double sum = 0.0;
    for (int k = 0; k < count; ++k) sum += inverseMass[k] * dot(gradient[k], gradient[k]);
    return sum;
  }
};

Linearised bending(const BendingTriple& t, const XpbdConstraints& xpbd, std::size_t first,
                   const std::vector<DVec3>& position) {
  Linearised c;
  const DVec3 centroid = (position[t.a] + position[t.middle] + position[t.b]) / 3.0;
  const DVec3 d = position[t.middle] - centroid;
  const double offset = norm(d);
  if (!(offset > 0.0)) return c;  // straight: no direction to push along, and C is at its least
  const DVec3 n = d / offset;
  c.particle[0] = t.a;
  c.particle[1] = t.middle;
  c.particle[2] = t.b;
  c.gradient[0] = n * (-1.0 / 3.0);
  c.gradient[1] = n * (2.0 / 3.0);
  c.gradient[2] = n * (-1.0 / 3.0);
  c.count = 3;
  c.value = offset - t.restOffset;
  c.valid = true;
  for (int k = 0; k < c.count; ++k) c.inverseMass[k] = xpbd.inverseMass[c.particle[k] - first];
  return c;
}

// One XPBD iteration with the multiplier starting from 0 (Macklin et al. 2019: λ is not carried
// between substeps): Δλ = −C / (Σ w |∇C|² + α / h²), Δx_i = w_i ∇_i C Δλ.
void project(const Linearised& c, double scaledCompliance, std::vector<DVec3>& position) {
  if (!c.valid) return;
  const double weight = c.weight();
  if (weight == 0.0) return;
  const double deltaLambda = -c.value / (weight + scaledCompliance);
  for (int k = 0; k < c.count; ++k)
    position[c.particle[k]] += c.gradient[k] * (c.inverseMass[k] * deltaLambda);
}

// The same for a spring, C = l − l0, ∇_b C = −∇_a C = the unit vector a → b, which it keeps for
// the damping pass.
void projectSpring(const Spring& spring, double wa, double wb, double scaledCompliance,
                   std::vector<DVec3>& position, DVec3& direction) {
  const DVec3 d = position[spring.b] - position[spring.a];
  const double l = norm(d);
  direction = l > 0.0 ? d / l : DVec3{0, 0, 0};
  const double w = wa + wb;
  if (w == 0.0 || !(l > 0.0)) return;
  const double deltaLambda = -(l - spring.restLength) / (w + scaledCompliance);
  position[spring.a] -= direction * (wa * deltaLambda);
  position[spring.b] += direction * (wb * deltaLambda);
}

// A dashpot of `hc` = h × c (N·s/m × s) along the constraint, implicit on the velocities after
// the position solve, as the velocity pass of Müller et al., "Detailed Rigid Body Simulation with
// Extended Position Based Dynamics" (2020), damps joints: the rate Ċ = ∇C·v becomes
// Ċ / (1 + h c Σ w |∇C|²). XPBD's own damping term acts on the substep's displacement, which
// includes the prediction under gravity: at rest it resists that prediction as if it were
// motion, and the tests' hanging chain settled 12 % longer than its compliance gives at
// h = 1.25e-4 s (the error halving with h). A velocity pass does nothing at rest.
void damp(const Linearised& c, double hc, std::vector<DVec3>& velocity) {
  if (!c.valid || hc == 0.0) return;
  const double weight = c.weight();
  if (weight == 0.0) return;
  double rate = 0.0;
  for (int k = 0; k < c.count; ++k) rate += dot(c.gradient[k], velocity[c.particle[k]]);
  const double impulse = -rate * hc / (1.0 + hc * weight);
  for (int k = 0; k < c.count; ++k)
    velocity[c.particle[k]] += c.gradient[k] * (c.inverseMass[k] * impulse);
}

void dampSpring(const Spring& spring, double wa, double wb, double hc, DVec3 direction,
                std::vector<DVec3>& velocity) {
  const double w = wa + wb;
  if (w == 0.0) return;
  const double rate = dot(velocity[spring.b] - velocity[spring.a], direction);
  const double impulse = rate * hc / (1.0 + hc * w);
  velocity[spring.a] += direction * (wa * impulse);
  velocity[spring.b] -= direction * (wb * impulse);
}

// Greedy colouring in spring order: each spring takes the lowest colour neither of its
// particles has yet. A shell has few springs per particle (the artery's vessel 14 on average at
// reach 2.2); a solid lattice at that reach has 56 and may run out of the 64 colours a mask
// holds: the rest then share the last colour, which costs speed, not correctness.
std::vector<std::uint32_t> colouredOrder(const SpringNetwork& net) {
  std::vector<std::uint64_t> used(net.count, 0);
  std::vector<std::pair<int, std::uint32_t>> coloured;
  for (std::size_t s = 0; s < net.springs.size(); ++s) {
    const Spring& spring = net.springs[s];
    std::uint64_t& a = used[spring.a - net.first];
    std::uint64_t& b = used[spring.b - net.first];
    const std::uint64_t taken = a | b;
    int colour = 0;
    while (colour < 63 && (taken >> colour & 1u)) ++colour;
    a |= std::uint64_t(1) << colour;
    b |= std::uint64_t(1) << colour;
    coloured.push_back({colour, std::uint32_t(s)});
  }
  std::stable_sort(coloured.begin(), coloured.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::uint32_t> order;
  order.reserve(coloured.size());
  for (const auto& [colour, s] : coloured) order.push_back(s);
  return order;
}

}  // namespace

std::vector<BendingTriple> buildBendingTriples(const SpringNetwork& net,
                                               const std::vector<DVec3>& position, double shell) {
  std::vector<BendingTriple> triples;
  std::vector<std::uint32_t> near;
  for (std::size_t k = 0; k < net.count; ++k) {
    const std::uint32_t middle = std::uint32_t(net.first + k);
    near.clear();
    for (std::uint32_t s = net.neighbourStart[k]; s < net.neighbourStart[k + 1]; ++s)
      if (norm(position[net.neighbours[s]] - position[middle]) < shell)
        near.push_back(net.neighbours[s]);
    for (std::size_t p = 0; p < near.size(); ++p)
      for (std::size_t q = p + 1; q < near.size(); ++q) {
        const DVec3 dp = position[near[p]] - position[middle];
        const DVec3 dq = position[near[q]] - position[middle];
        if (dot(dp, dq) >= kStraightCosine * norm(dp) * norm(dq)) continue;
        const std::uint32_t a = std::min(near[p], near[q]), b = std::max(near[p], near[q]);
        const DVec3 centroid = (position[a] + position[middle] + position[b]) / 3.0;
        // Neighbours within the reach are joined by springs, so both spanned springs exist.
        const std::size_t first = findSpring(net.springs, std::min(a, middle), std::max(a, middle));
        const std::size_t second =
            findSpring(net.springs, std::min(b, middle), std::max(b, middle));
        triples.push_back({a,
                           middle,
                           b,
                           norm(position[middle] - centroid),
                           {std::uint32_t(first), std::uint32_t(second)}});
      }
  }
  return triples;
}

XpbdConstraints makeXpbdConstraints(const SpringNetwork& net, const std::vector<DVec3>& position,
                                    const std::vector<float>& mass,
                                    const std::vector<std::uint8_t>& pinned, double shell,
                                    double bendingStiffness, int substeps) {
  XpbdConstraints xpbd;
  xpbd.substeps = substeps;
  xpbd.bendingStiffness = bendingStiffness;
  if (bendingStiffness > 0.0) xpbd.bending = buildBendingTriples(net, position, shell);
  xpbd.bendingBroken.assign(xpbd.bending.size(), 0);
  xpbd.inverseMass.resize(net.count);
  for (std::size_t k = 0; k < net.count; ++k) {
    const std::size_t i = net.first + k;
    xpbd.inverseMass[k] = pinned[i] ? 0.0 : 1.0 / double(mass[i]);
  }
  xpbd.springOrder = colouredOrder(net);
  xpbd.direction.resize(net.springs.size());
  xpbd.previous.resize(net.count);
  return xpbd;
}

void breakBendingAcrossTears(const SpringNetwork& net, XpbdConstraints& xpbd) {
  for (std::size_t t = 0; t < xpbd.bending.size(); ++t) {
    const BendingTriple& triple = xpbd.bending[t];
    if (net.broken[triple.spanned[0]] || net.broken[triple.spanned[1]]) xpbd.bendingBroken[t] = 1;
  }
}

void xpbdPredict(const SpringNetwork& net, XpbdConstraints& xpbd, double h, DVec3 gravity,
                 const std::vector<DVec3>& force, std::vector<DVec3>& position,
                 std::vector<DVec3>& velocity) {
  for (std::size_t k = 0; k < net.count; ++k) {
    const std::size_t i = net.first + k;
    const double w = xpbd.inverseMass[k];
    xpbd.previous[k] = position[i];
    if (w == 0.0) continue;
    velocity[i] += (force[i] * w + gravity) * h;
    position[i] += velocity[i] * h;
  }
}

void xpbdProject(const SpringNetwork& net, XpbdConstraints& xpbd, double h,
                 std::vector<DVec3>& position) {
  const std::size_t first = net.first;
  const std::vector<double>& w = xpbd.inverseMass;
  const double springCompliance = 1.0 / (net.stiffness * h * h);
  for (std::uint32_t s : xpbd.springOrder) {
    if (net.broken[s]) continue;
    const Spring& spring = net.springs[s];
    projectSpring(spring, w[spring.a - first], w[spring.b - first], springCompliance, position,
                  xpbd.direction[s]);
  }
  const double bendingCompliance =
      xpbd.bendingStiffness > 0.0 ? 1.0 / (xpbd.bendingStiffness * h * h) : 0.0;
  for (std::size_t t = 0; t < xpbd.bending.size(); ++t)
    if (!xpbd.bendingBroken[t])
      project(bending(xpbd.bending[t], xpbd, first, position), bendingCompliance, position);
}

void xpbdFinish(SpringNetwork& net, XpbdConstraints& xpbd, double h,
                const std::vector<DVec3>& position, std::vector<DVec3>& velocity,
                std::vector<std::uint8_t>& cut) {
  const std::size_t first = net.first;
  const std::vector<double>& w = xpbd.inverseMass;
  for (std::size_t k = 0; k < net.count; ++k)
    if (w[k] > 0.0) velocity[first + k] = (position[first + k] - xpbd.previous[k]) / h;

  // Bending triples damp in the springs' proportion c / k: the same relaxation time.
  const double springDamping = h * net.damping;
  for (std::uint32_t s : xpbd.springOrder) {
    if (net.broken[s]) continue;
    const Spring& spring = net.springs[s];
    dampSpring(spring, w[spring.a - first], w[spring.b - first], springDamping, xpbd.direction[s],
               velocity);
  }
  const double bendingDamping = springDamping * xpbd.bendingStiffness / net.stiffness;
  for (std::size_t t = 0; t < xpbd.bending.size(); ++t)
    if (!xpbd.bendingBroken[t])
      damp(bending(xpbd.bending[t], xpbd, first, position), bendingDamping, velocity);

  breakOverstretched(net, position, cut);
  breakBendingAcrossTears(net, xpbd);
}

}  // namespace sph::objects
