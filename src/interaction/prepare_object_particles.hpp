// Stage (when the engine publishes): the objects' surface particles sorted by the cells of a
// grid over them, handed to backend B. Sorted on the host with the CPU primitives: they come
// from the host engine, and there are few of them next to the fluid.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "interaction/object_particles.hpp"
#include "interaction/prepare_object_boundary.hpp"
#include "sph/object_exchange.hpp"

namespace sph::interaction {

// Returns the largest speed of an object particle inside the domain (the box the fluid can
// be in), m/s: a torn piece falling away below it limits nothing.
// With boundary coupling (params.boundary) also the same particles as the fluid's boundary
// particles (prepare_object_boundary.hpp); else `boundary` is left empty.
template <class B>
float prepareObjectParticles(ObjectParticles<B>& objects, fluid::BoundaryParticles<B>& boundary,
                             const ObjectSurface& surface, const InteractionParameters& params,
                             const fluid::FluidParameters& fluidParams, Vec3 domainMin,
                             Vec3 domainMax) {
  // Only the particles the fluid can reach: within the domain, or a reach outside it. A piece
  // torn off and falling away would otherwise stretch the grid over its whole fall.
  float reach = 0.0f;
  for (std::size_t k = 0; k < surface.size(); ++k)
    reach = fmaxf(reach, contactReach(params, radiusOf(surface.position[k])));
  const float margin = params.boundary ? fmaxf(reach, fluidParams.h) : reach;
  std::vector<std::uint32_t> kept;
  for (std::size_t k = 0; k < surface.size(); ++k) {
    const Vec3 p = xyz(surface.position[k]);
    if (p.x >= domainMin.x - margin && p.y >= domainMin.y - margin && p.z >= domainMin.z - margin &&
        p.x <= domainMax.x + margin && p.y <= domainMax.y + margin && p.z <= domainMax.z + margin)
      kept.push_back(std::uint32_t(k));
  }
  const std::size_t n = kept.size();
  objects.count = n;
  boundary.count = 0;
  objects.force.resize(n);
  if (n == 0) return 0.0f;
  Vec3 lo = xyz(surface.position[kept[0]]), hi = lo;
  float maxSpeed2 = 0.0f;
  for (std::uint32_t k : kept) {
    const Vec3 p = xyz(surface.position[k]);
    lo = Vec3{fminf(lo.x, p.x), fminf(lo.y, p.y), fminf(lo.z, p.z)};
    hi = Vec3{fmaxf(hi.x, p.x), fmaxf(hi.y, p.y), fmaxf(hi.z, p.z)};
    const bool inDomain = p.x >= domainMin.x && p.y >= domainMin.y && p.z >= domainMin.z &&
                          p.x <= domainMax.x && p.y <= domainMax.y && p.z <= domainMax.z;
    if (inDomain) maxSpeed2 = fmaxf(maxSpeed2, lengthSquared(xyz(surface.velocity[k])));
  }
  // Boundary particles are found through this grid from the fluid, out to h.
  objects.grid = makeGrid(lo, hi, margin);
  const GridSpec grid = objects.grid;
  std::vector<std::uint32_t> cell(n), order(n), cellStart(grid.cellCount + 1);
  for (std::size_t k = 0; k < n; ++k)
    cell[k] =
        cellIndex(grid, clampToGrid(grid, cellCoordinate(grid, xyz(surface.position[kept[k]]))));
  backend::countingSort(cell.data(), n, grid.cellCount, order.data(), cellStart.data());

  std::vector<Vec4> position(n), velocity(n), normal(n);
  std::vector<std::uint32_t> handle(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t s = kept[order[k]];
    position[k] = packPosition(xyz(surface.position[s]), radiusOf(surface.position[s]));
    velocity[k] = packVelocity(xyz(surface.velocity[s]), surface.cut[s] != 0);
    normal[k] = packNormal(xyz(surface.normal[s]), surface.object[s]);
    handle[k] = surface.handle[s];
  }
  B::upload(objects.position, position.data(), n);
  B::upload(objects.velocity, velocity.data(), n);
  B::upload(objects.normal, normal.data(), n);
  B::upload(objects.handle, handle.data(), n);
  B::upload(objects.cellStart, cellStart.data(), cellStart.size());
  if (params.boundary)
    prepareObjectBoundary(boundary, position, velocity, cellStart, grid, fluidParams);

  std::int32_t objectCount = 0;
  for (std::int32_t o : surface.object) objectCount = o + 1 > objectCount ? o + 1 : objectCount;
  const float big = 3.0e38f;
  std::vector<Vec4> bounds(2 * std::size_t(objectCount));
  for (std::int32_t o = 0; o < objectCount; ++o) {
    bounds[2 * o] = Vec4{big, big, big, 0};
    bounds[2 * o + 1] = Vec4{-big, -big, -big, 0};
  }
  for (std::size_t k = 0; k < n; ++k) {
    // Torn particles can hang loose, far from the vessel they came from: the box is the
    // intact wall's.
    if (surface.cut[k]) continue;
    const Vec3 p = xyz(surface.position[k]);
    const float r = contactReach(params, radiusOf(surface.position[k]));
    Vec4& lo = bounds[2 * std::size_t(surface.object[k])];
    Vec4& hi = bounds[2 * std::size_t(surface.object[k]) + 1];
    lo = Vec4{fminf(lo.x, p.x - r), fminf(lo.y, p.y - r), fminf(lo.z, p.z - r), 0};
    hi = Vec4{fmaxf(hi.x, p.x + r), fmaxf(hi.y, p.y + r), fmaxf(hi.z, p.z + r), 0};
  }
  for (Vec4& corner : bounds) {  // an object torn all over has no intact box: no bound
    if (corner.x == big)
      corner = Vec4{-big, -big, -big, 0};
    else if (corner.x == -big)
      corner = Vec4{big, big, big, 0};
  }
  B::upload(objects.bounds, bounds.data(), bounds.size());
  return std::sqrt(maxSpeed2);
}

}  // namespace sph::interaction
