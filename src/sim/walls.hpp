// The scene's walls as boundary particles (Akinci et al. 2012), and the room they leave for the
// fluid's initial lattice.
#pragma once

#include <memory>
#include <vector>

#include "sph/core/vec.hpp"
#include "sph/scene.hpp"

namespace sph::sim {

class Walls {
 public:
  // Samples every wall of `scene` at the fluid's spacing: `layers` layers on the side away from
  // the fluid, the first half a spacing behind the surface the fluid meets. Throws InputError
  // naming the scene file and the wall's key (a mesh that is missing, empty, unreadable or not
  // closed when it should be; a shape too thin for its layers).
  explicit Walls(const Scene& scene);
  ~Walls();
  Walls(Walls&&) noexcept;
  Walls& operator=(Walls&&) noexcept;

  // The walls' particles, then their periodic images (copies across a periodic face, for the
  // fluid near it), which belong to no wall.
  const std::vector<Vec3>& particles() const { return particles_; }
  // Wall w's particles are [firstParticle()[w], firstParticle()[w + 1]) of particles(); the
  // images follow the last wall's.
  const std::vector<std::size_t>& firstParticle() const { return firstParticle_; }

  // Removes the points that lie on a wall's solid side (inside an obstacle, outside a closed
  // container) or nearer than 3/4 of a spacing to a wall particle, where a fluid particle would
  // start overlapping the wall. Keeps the order of the points that remain.
  void removeOverlap(std::vector<Vec3>& points) const;

 private:
  struct Solids;
  std::vector<Vec3> particles_;
  std::vector<std::size_t> firstParticle_;
  std::unique_ptr<Solids> solids_;
};

}  // namespace sph::sim
