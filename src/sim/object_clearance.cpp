#include "sim/object_clearance.hpp"

#include <algorithm>

#include "objects/math3d.hpp"
#include "objects/point_grid.hpp"

namespace sph::sim {

void removeObjectOverlap(std::vector<Vec3>& points, const objects::ObjectWorld& world,
                         const std::function<float(float)>& reachOf, int container) {
  const objects::ParticleState& particles = world.particles();
  if (particles.size() == 0) return;
  std::vector<objects::DVec3> centres(particles.size());
  std::vector<double> reach(particles.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    centres[i] = objects::toD(particles.position[i]);
    reach[i] = reachOf(particles.radius[i]);
    largest = std::max(largest, reach[i]);
  }
  objects::PointGrid grid;
  grid.build(centres, largest);

  const auto blocked = [&](Vec3 point) {
    const objects::DVec3 p = objects::toD(point);
    bool near = false;
    grid.forEachCandidate(p, largest, [&](std::uint32_t i) {
      if (objects::norm(centres[i] - p) < reach[i]) near = true;
    });
    if (near) return true;
    for (std::size_t o = 0; o < world.objectCount(); ++o)
      if (int(o) != container && world.interiorContains(o, point, 0.0f)) return true;
    return false;
  };
  points.erase(std::remove_if(points.begin(), points.end(), blocked), points.end());
}

}  // namespace sph::sim
