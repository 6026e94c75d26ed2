#include "sim/outputs.hpp"

#include <algorithm>
#include <cstdint>

namespace sph::sim {

bool Outputs::probesWallForces(const Scene& scene) {
  for (const ProbeDesc& p : scene.probes)
    if (p.kind == ProbeKind::Force && !p.wall.empty()) return true;
  return false;
}

void Outputs::mapWallParticles(FluidEngine& engine, const Walls& walls, const Scene& scene,
                               std::size_t initialFluid) {
  const HostWalls host = engine.downloadWalls();
  const std::vector<std::size_t>& first = walls.firstParticle();
  wallOfParticle.resize(host.id.size());
  for (std::size_t k = 0; k < host.id.size(); ++k) {
    const std::size_t sampled = host.id[k] - initialFluid;  // wall ids follow the fluid's
    wallOfParticle[k] =
        std::size_t(std::upper_bound(first.begin(), first.end(), sampled) - first.begin()) - 1;
  }
  fluidForceOnWall.assign(scene.walls.size(), Vec3{0, 0, 0});
  std::vector<std::uint8_t> probed(scene.walls.size(), 0), watched(host.id.size(), 0);
  for (const ProbeDesc& p : scene.probes)
    for (std::size_t w = 0; w < scene.walls.size(); ++w)
      if (p.kind == ProbeKind::Force && p.wall == scene.walls[w].name) probed[w] = 1;
  // A periodic image belongs to no wall (its index is past the last): never watched.
  for (std::size_t k = 0; k < watched.size(); ++k)
    watched[k] = wallOfParticle[k] < probed.size() ? probed[wallOfParticle[k]] : 0;
  engine.watchWalls(watched);
}

void Outputs::collectWallForces(FluidEngine& engine) {
  const std::vector<Vec4> force = engine.wallForces();
  std::vector<double> sum(3 * fluidForceOnWall.size(), 0.0);
  for (std::size_t k = 0; k < force.size(); ++k) {
    if (wallOfParticle[k] >= fluidForceOnWall.size()) continue;  // a periodic image
    double* s = &sum[3 * wallOfParticle[k]];
    s[0] += force[k].x;
    s[1] += force[k].y;
    s[2] += force[k].z;
  }
  for (std::size_t w = 0; w < fluidForceOnWall.size(); ++w)
    fluidForceOnWall[w] = Vec3{float(sum[3 * w]), float(sum[3 * w + 1]), float(sum[3 * w + 2])};
}

void Outputs::sampleProbes(FluidEngine& engine, double time,
                           const std::vector<Vec3>& fluidForceOnObject,
                           const std::vector<Vec3>& contactForceOnObject) {
  if (probes->empty()) return;
  probes->record(time, engine.samplePoints(probes->points()),
                 {fluidForceOnObject, contactForceOnObject, fluidForceOnWall});
}

}  // namespace sph::sim
