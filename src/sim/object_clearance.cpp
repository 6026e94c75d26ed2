#include "sim/object_clearance.hpp"

#include <algorithm>

#include "objects/math3d.hpp"
#include "objects/point_grid.hpp"

namespace sph::sim {

namespace {

// Calls visit(shift) for every combination of −L, 0 and +L along the periodic axes: an
// object's as-built shape may reach past a face, and a point may lie past it as its image.
template <class Visit>
void forEachNeighbourPeriod(const objects::PeriodicSpace& space, Visit&& visit) {
  const double length[3] = {space.length.x, space.length.y, space.length.z};
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        const int s[3] = {i, j, k};
        bool possible = true;
        for (int a = 0; a < 3; ++a) possible = possible && (s[a] == 0 || space.periodic[a]);
        if (possible) visit(objects::DVec3{s[0] * length[0], s[1] * length[1], s[2] * length[2]});
      }
}

}  // namespace

void removeObjectOverlap(std::vector<Vec3>& points, const objects::ObjectWorld& world,
                         const std::function<float(float)>& reachOf, int container) {
  const objects::ParticleState& particles = world.particles();
  if (particles.size() == 0) return;
  const objects::PeriodicSpace& space = world.periodicSpace();
  std::vector<objects::DVec3> centres(particles.size());
  std::vector<double> reach(particles.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    centres[i] = space.wrapped(objects::toD(particles.position[i]));
    reach[i] = reachOf(particles.radius[i]);
    largest = std::max(largest, reach[i]);
  }
  objects::PointGrid grid;
  grid.build(centres, largest);

  const auto blocked = [&](Vec3 point) {
    const objects::DVec3 p = space.wrapped(objects::toD(point));
    bool near = false;
    space.forEachImage(p, largest, [&](objects::DVec3 shift) {
      grid.forEachCandidate(p + shift, largest, [&](std::uint32_t i) {
        if (objects::norm(centres[i] - (p + shift)) < reach[i]) near = true;
      });
    });
    if (near) return true;
    bool inside = false;
    for (std::size_t o = 0; o < world.objectCount() && !inside; ++o) {
      if (int(o) == container) continue;
      forEachNeighbourPeriod(space, [&](objects::DVec3 shift) {
        inside = inside || world.interiorContains(o, objects::toF(p + shift), 0.0f);
      });
    }
    return inside;
  };
  points.erase(std::remove_if(points.begin(), points.end(), blocked), points.end());
}

}  // namespace sph::sim
