#include "objects/contact_constraints.hpp"

#include <cmath>

namespace sph::objects {

namespace {

// The unit vector from b to a and their distance; a zero vector where they coincide.
struct Separation {
  DVec3 normal;
  double distance;
};

Separation separation(const PeriodicSpace& space, DVec3 a, DVec3 b) {
  const DVec3 d = space.any() ? space.nearest(a - b) : a - b;
  const double l = norm(d);
  return {l > 0.0 ? d / l : DVec3{0, 0, 0}, l};
}

// The impulse on a (b takes its negation) that brings the relative velocity `rate` (of b
// against a, along one direction) to rate / (1 + h c w): the dashpot of coefficient c
// integrated implicitly over h, w the pair's summed inverse mass.
DVec3 implicitDashpot(DVec3 rate, double hc, double w) {
  return rate * (hc / (1.0 + hc * w));
}

}  // namespace

void findContactCandidates(const ContactParticles& p, float maxRadius, double margin,
                           const StaticParticles& statics, ContactConstraints& contacts) {
  contacts.candidates.clear();
  const double reachMax = 2.0 * double(maxRadius) + margin;
  ContactSearch& search = contacts.search;
  markNearOtherObjects(p, reachMax, search);
  const std::vector<DVec3>& position = searchPositions(p, search);
  search.grid.build(position, reachMax, search.near);
  // Each pair once, through the one image of i that reaches the other particle: the distance
  // is taken from that image, not to the nearest.
  const auto distance = [](DVec3 a, DVec3 b) { return norm(a - b); };
  for (std::size_t i = 0; i < position.size(); ++i) {
    if (p.role[i] != ContactRole::Projected) continue;
    const std::uint32_t a = std::uint32_t(i);
    if (search.near[i])
      p.space.forEachImage(position[i], reachMax, [&](DVec3 shift) {
        const DVec3 xi = position[i] + shift;
        search.grid.forEachCandidate(xi, reachMax, [&](std::uint32_t j) {
          if (p.object[j] == p.object[i] || p.role[j] == ContactRole::Pushed) return;
          if (p.role[j] == ContactRole::Projected && j <= i) return;
          const double reach = double(p.radius[i]) + double(p.radius[j]) + margin;
          if (distance(xi, position[j]) < reach) contacts.candidates.push_back({a, j, false});
        });
      });
    if (statics.position.empty()) continue;
    const double reach = double(p.radius[i]) + double(statics.radius) + margin;
    p.space.forEachImage(position[i], reach, [&](DVec3 shift) {
      const DVec3 xi = position[i] + shift;
      statics.grid.forEachCandidate(xi, reach, [&](std::uint32_t j) {
        if (distance(xi, statics.position[j]) < reach) contacts.candidates.push_back({a, j, true});
      });
    });
  }
}

void selectTouching(const std::vector<DVec3>& position, const std::vector<float>& radius,
                    const StaticParticles& statics, ContactConstraints& contacts) {
  contacts.touching.clear();
  for (const ConstraintContact& c : contacts.candidates) {
    const DVec3 xb = c.againstStatic ? statics.position[c.b] : position[c.b];
    const double rb = c.againstStatic ? double(statics.radius) : double(radius[c.b]);
    if (separation(contacts.space, position[c.a], xb).distance < double(radius[c.a]) + rb)
      contacts.touching.push_back(c);
  }
}

void projectContactConstraints(const ContactCoefficients& k, double h,
                               const std::vector<double>& inverseMass,
                               const std::vector<float>& radius,
                               const std::vector<std::int32_t>& object,
                               const StaticParticles& statics, const ContactConstraints& contacts,
                               std::vector<DVec3>& position, std::vector<DVec3>& impulse) {
  // α̃ = α / h², α = 1 / k_spring; a contact without a spring is hard.
  const double compliance = k.spring > 0.0f ? 1.0 / (double(k.spring) * h * h) : 0.0;
  for (const ConstraintContact& c : contacts.touching) {
    const DVec3 xb = c.againstStatic ? statics.position[c.b] : position[c.b];
    const double rb = c.againstStatic ? double(statics.radius) : double(radius[c.b]);
    const Separation s = separation(contacts.space, position[c.a], xb);
    const double overlap = double(radius[c.a]) + rb - s.distance;
    if (!(overlap > 0.0) || !(s.distance > 0.0)) continue;
    const double wa = inverseMass[c.a], wb = c.againstStatic ? 0.0 : inverseMass[c.b];
    const double lambda = overlap / (wa + wb + compliance);  // −C / (Σ w |∇C|² + α̃)
    position[c.a] += s.normal * (wa * lambda);
    const DVec3 pushOnA = s.normal * (lambda / h);
    impulse[std::size_t(object[c.a])] += pushOnA;
    if (c.againstStatic) continue;
    position[c.b] -= s.normal * (wb * lambda);
    impulse[std::size_t(object[c.b])] -= pushOnA;
  }
}

void dampContactConstraints(const ContactCoefficients& k, double h,
                            const std::vector<double>& inverseMass,
                            const std::vector<std::int32_t>& object, const StaticParticles& statics,
                            const ContactConstraints& contacts, const std::vector<DVec3>& position,
                            std::vector<DVec3>& velocity, std::vector<DVec3>& impulse) {
  const double normalRate = h * double(k.damping);
  const double tangentRate = h * (double(k.damping) + double(k.shear));
  if (normalRate == 0.0 && tangentRate == 0.0) return;
  const DVec3 still{0, 0, 0};
  for (const ConstraintContact& c : contacts.touching) {
    const DVec3 xb = c.againstStatic ? statics.position[c.b] : position[c.b];
    const Separation s = separation(contacts.space, position[c.a], xb);
    if (!(s.distance > 0.0)) continue;
    const double wa = inverseMass[c.a], wb = c.againstStatic ? 0.0 : inverseMass[c.b];
    const double w = wa + wb;
    const DVec3 vb = c.againstStatic ? still : velocity[c.b];
    const DVec3 relative = vb - velocity[c.a];       // as the force law: v_b − v_a
    const double closing = dot(relative, s.normal);  // > 0: b comes on at a
    const DVec3 normalPart = s.normal * closing;
    // The position solve has already parted them; a dashpot that held them together as they
    // part would be a glue no contact has.
    const DVec3 push = (closing > 0.0 ? implicitDashpot(normalPart, normalRate, w) : DVec3{}) +
                       implicitDashpot(relative - normalPart, tangentRate, w);
    velocity[c.a] += push * wa;
    impulse[std::size_t(object[c.a])] += push;
    if (c.againstStatic) continue;
    velocity[c.b] -= push * wb;
    impulse[std::size_t(object[c.b])] -= push;
  }
}

}  // namespace sph::objects
