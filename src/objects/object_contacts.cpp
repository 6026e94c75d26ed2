#include "objects/object_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph::objects {

namespace {

bool inBox(const DVec3& x, const DVec3& lo, const DVec3& hi) {
  return x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x <= hi.x && x.y <= hi.y && x.z <= hi.z;
}

}  // namespace

const std::vector<DVec3>& searchPositions(const ContactParticles& p, const ContactSearch& s) {
  return p.space.any() ? s.wrapped : p.position;
}

// Two particles in contact are both marked; a vessel's thousands of particles, of which a clamp
// touches a few hundred, are mostly not, and are neither sorted into the grid nor searched from.
void markNearOtherObjects(const ContactParticles& p, double reach, ContactSearch& s) {
  const std::size_t n = p.position.size();
  if (p.space.any()) {
    s.wrapped.resize(n);
    for (std::size_t i = 0; i < n; ++i) s.wrapped[i] = p.space.wrapped(p.position[i]);
  }
  const std::vector<DVec3>& position = searchPositions(p, s);
  std::size_t objects = 0;
  for (std::size_t i = 0; i < n; ++i) objects = std::max(objects, std::size_t(p.object[i]) + 1);
  const double big = std::numeric_limits<double>::infinity();
  s.boxMin.assign(objects, DVec3{big, big, big});
  s.boxMax.assign(objects, DVec3{-big, -big, -big});
  s.near.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const DVec3& x = position[i];
    if (!inBox(x, p.regionMin, p.regionMax)) continue;
    DVec3& lo = s.boxMin[std::size_t(p.object[i])];
    DVec3& hi = s.boxMax[std::size_t(p.object[i])];
    lo = {std::min(lo.x, x.x), std::min(lo.y, x.y), std::min(lo.z, x.z)};
    hi = {std::max(hi.x, x.x), std::max(hi.y, x.y), std::max(hi.z, x.z)};
  }
  const DVec3 grow{reach, reach, reach};
  for (std::size_t o = 0; o < objects; ++o) {
    s.boxMin[o] = s.boxMin[o] - grow;
    s.boxMax[o] = s.boxMax[o] + grow;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const DVec3& x = position[i];
    // NaN positions are kept, so that a diverged run still meets its contacts and fails.
    const bool finite = std::isfinite(x.x + x.y + x.z);
    if (finite && !inBox(x, p.regionMin, p.regionMax)) continue;
    if (!finite) {
      s.near[i] = objects > 1 ? 1 : 0;
      continue;
    }
    p.space.forEachImage(x, reach, [&](DVec3 shift) {
      for (std::size_t o = 0; o < objects && !s.near[i]; ++o)
        s.near[i] = o != std::size_t(p.object[i]) && inBox(x + shift, s.boxMin[o], s.boxMax[o]);
    });
  }
}

std::size_t addContactForces(const ContactCoefficients& coefficients, const ContactParticles& p,
                             float maxRadius, ContactSearch& search, std::vector<DVec3>& force) {
  const double reachMax = 2.0 * double(maxRadius);
  markNearOtherObjects(p, reachMax, search);
  const std::vector<DVec3>& position = searchPositions(p, search);
  PointGrid& grid = search.grid;
  grid.build(position, reachMax, search.near);
  std::size_t touching = 0;
  for (std::size_t i = 0; i < position.size(); ++i) {
    // Pairs are found from a particle that can move (kinematic floors hold many particles that
    // need no search); each pair once: from the lower index when both can move, through the
    // one image of i that reaches j. The order is fixed, so the sums are the same on every run.
    if (p.role[i] == ContactRole::Fixed || !search.near[i]) continue;
    p.space.forEachImage(position[i], reachMax, [&](DVec3 shift) {
      const DVec3 xi = position[i] + shift;
      grid.forEachCandidate(xi, reachMax, [&](std::uint32_t j) {
        if (p.object[j] == p.object[i] || (p.role[j] != ContactRole::Fixed && j <= i)) return;
        // Between two particles neither of which is pushed, the contact is a constraint.
        if (p.role[i] != ContactRole::Pushed && p.role[j] != ContactRole::Pushed) return;
        const float reach = p.radius[i] + p.radius[j];
        const Vec3 offset = toF(xi - position[j]);
        if (lengthSquared(offset) >= reach * reach) return;
        const Vec3 relativeVelocity = toF(p.velocity[j] - p.velocity[i]);
        const DVec3 f = toD(demContactForce(coefficients, offset, relativeVelocity, reach,
                                            /*springScale=*/1.0f, /*damped=*/true));
        force[i] += f;
        force[j] -= f;
        ++touching;
      });
    });
  }
  return touching;
}

std::size_t addStaticContactForces(const ContactCoefficients& coefficients,
                                   const ContactParticles& p, const std::vector<DVec3>& statics,
                                   float staticRadius, const PointGrid& staticGrid,
                                   std::vector<DVec3>& force) {
  std::size_t touching = 0;
  for (std::size_t i = 0; i < p.position.size(); ++i) {
    if (p.role[i] != ContactRole::Pushed) continue;
    const float reach = p.radius[i] + staticRadius;
    const DVec3 wrapped = p.space.wrapped(p.position[i]);
    p.space.forEachImage(wrapped, reach, [&](DVec3 shift) {
      const DVec3 xi = wrapped + shift;
      staticGrid.forEachCandidate(xi, reach, [&](std::uint32_t j) {
        const Vec3 offset = toF(xi - statics[j]);
        if (lengthSquared(offset) >= reach * reach) return;
        force[i] += toD(demContactForce(coefficients, offset, toF(-p.velocity[i]), reach,
                                        /*springScale=*/1.0f, /*damped=*/true));
        ++touching;
      });
    });
  }
  return touching;
}

}  // namespace sph::objects
