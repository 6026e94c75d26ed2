#include "objects/object_contacts.hpp"

namespace sph::objects {

std::size_t addContactForces(const ContactCoefficients& coefficients, const ContactParticles& p,
                             float maxRadius, PointGrid& grid, std::vector<DVec3>& force) {
  const double reachMax = 2.0 * double(maxRadius);
  grid.build(p.position, reachMax, p.regionMin, p.regionMax);
  std::size_t touching = 0;
  for (std::size_t i = 0; i < p.position.size(); ++i) {
    // Pairs are found from a particle that can move (kinematic floors hold many particles that
    // need no search); each pair once: from the lower index when both can move. The order is
    // fixed, so the sums are the same on every run.
    if (!p.movable[i]) continue;
    grid.forEachCandidate(p.position[i], reachMax, [&](std::uint32_t j) {
      if (p.object[j] == p.object[i] || (p.movable[j] && j <= i)) return;
      const float reach = p.radius[i] + p.radius[j];
      const Vec3 offset = toF(p.position[i] - p.position[j]);
      if (lengthSquared(offset) >= reach * reach) return;
      const Vec3 relativeVelocity = toF(p.velocity[j] - p.velocity[i]);
      const DVec3 f = toD(demContactForce(coefficients, offset, relativeVelocity, reach,
                                          /*springScale=*/1.0f, /*damped=*/true));
      force[i] += f;
      force[j] -= f;
      ++touching;
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
    if (!p.movable[i]) continue;
    const float reach = p.radius[i] + staticRadius;
    staticGrid.forEachCandidate(p.position[i], reach, [&](std::uint32_t j) {
      const Vec3 offset = toF(p.position[i] - statics[j]);
      if (lengthSquared(offset) >= reach * reach) return;
      force[i] += toD(demContactForce(coefficients, offset, toF(-p.velocity[i]), reach,
                                      /*springScale=*/1.0f, /*damped=*/true));
      ++touching;
    });
  }
  return touching;
}

}  // namespace sph::objects
