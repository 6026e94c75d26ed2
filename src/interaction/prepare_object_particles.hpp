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
#include "sph/core/periodic.hpp"
#include "sph/object_exchange.hpp"

namespace sph::interaction {

namespace detail {

// Calls add(x) for x, moved by whole periods into the domain (an object is kept whole by its
// engine, so its particles may lie any distance past a face), and for each of its images that
// lies within `reach` of the domain beyond the opposite face.
template <class Add>
void forEachImageInReach(const Periodicity& p, Vec3 x, float reach, Add&& add) {
  if (isPeriodic(p, 0)) x.x = intoPeriod(x.x, p.lo.x, p.length.x);
  if (isPeriodic(p, 1)) x.y = intoPeriod(x.y, p.lo.y, p.length.y);
  if (isPeriodic(p, 2)) x.z = intoPeriod(x.z, p.lo.z, p.length.z);
  const bool periodic[3] = {isPeriodic(p, 0), isPeriodic(p, 1), isPeriodic(p, 2)};
  const float at[3] = {x.x, x.y, x.z}, lo[3] = {p.lo.x, p.lo.y, p.lo.z};
  const float hi[3] = {p.hi.x, p.hi.y, p.hi.z};
  forEachPeriodicImage(periodic, at, lo, hi, reach, [&](const int s[3]) {
    add(x + Vec3{float(s[0]) * p.length.x, float(s[1]) * p.length.y, float(s[2]) * p.length.z});
  });
}

}  // namespace detail

// Returns the largest speed of an object particle inside the domain (the box the fluid can
// be in), m/s: a torn piece falling away below it limits nothing.
// With boundary coupling (params.boundary) also the same particles as the fluid's boundary
// particles (prepare_object_boundary.hpp); else `boundary` is left empty.
//
// Along a periodic axis each particle is moved into the domain, and one near a face is also
// copied, as its image, beyond the opposite face, with the same handle: the fluid near that
// face then finds it as a plain neighbour, both passes meet each pair once with the same
// arguments, and the forces on a particle and its images add up in the exchange.
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
  std::vector<Vec3> at;             // where each kept particle or image lies
  std::vector<std::uint32_t> from;  // its index in `surface`
  for (std::size_t k = 0; k < surface.size(); ++k)
    detail::forEachImageInReach(fluidParams.periodic, xyz(surface.position[k]), margin,
                                [&](Vec3 p) {
                                  if (p.x >= domainMin.x - margin && p.y >= domainMin.y - margin &&
                                      p.z >= domainMin.z - margin && p.x <= domainMax.x + margin &&
                                      p.y <= domainMax.y + margin && p.z <= domainMax.z + margin) {
                                    at.push_back(p);
                                    from.push_back(std::uint32_t(k));
                                  }
                                });
  const std::size_t n = at.size();
  objects.count = n;
  boundary.count = 0;
  objects.force.resize(n);
  if (n == 0) return 0.0f;
  Vec3 lo = at[0], hi = lo;
  float maxSpeed2 = 0.0f;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 p = at[k];
    lo = Vec3{fminf(lo.x, p.x), fminf(lo.y, p.y), fminf(lo.z, p.z)};
    hi = Vec3{fmaxf(hi.x, p.x), fmaxf(hi.y, p.y), fmaxf(hi.z, p.z)};
    const bool inDomain = p.x >= domainMin.x && p.y >= domainMin.y && p.z >= domainMin.z &&
                          p.x <= domainMax.x && p.y <= domainMax.y && p.z <= domainMax.z;
    if (inDomain) maxSpeed2 = fmaxf(maxSpeed2, lengthSquared(xyz(surface.velocity[from[k]])));
  }
  // Boundary particles are found through this grid from the fluid, out to h.
  objects.grid = makeGrid(lo, hi, margin);
  const GridSpec grid = objects.grid;
  std::vector<std::uint32_t> cell(n), order(n), cellStart(grid.cellCount + 1);
  for (std::size_t k = 0; k < n; ++k)
    cell[k] = cellIndex(grid, clampToGrid(grid, cellCoordinate(grid, at[k])));
  backend::countingSort(cell.data(), n, grid.cellCount, order.data(), cellStart.data());

  std::vector<Vec4> position(n), velocity(n), normal(n);
  std::vector<std::uint32_t> handle(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t s = from[order[k]];
    position[k] = packPosition(at[order[k]], radiusOf(surface.position[s]));
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
    if (isCut(velocity[k])) continue;
    const Vec3 p = xyz(position[k]);
    const float r = contactReach(params, radiusOf(position[k]));
    Vec4& lo = bounds[2 * std::size_t(objectOf(normal[k]))];
    Vec4& hi = bounds[2 * std::size_t(objectOf(normal[k])) + 1];
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
