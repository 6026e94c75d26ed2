#include <cmath>

#include "backend/cpu_parallel.hpp"
#include "fluid/stages.hpp"

namespace sph::fluid {

namespace {

SPH_HD bool insideDomain(const DomainParameters& d, Vec3 p) {
  // Written so that NaN compares as outside.
  return p.x >= d.min.x && p.x <= d.max.x && p.y >= d.min.y && p.y <= d.max.y && p.z >= d.min.z &&
         p.z <= d.max.z;
}

// The extent of the particles inside the domain; NaN positions count as outside.
struct Bounds {
  Vec3 lo, hi;
  bool any;
};

SPH_HD Bounds merge(const Bounds& a, const Bounds& b) {
  if (!a.any) return b;
  if (!b.any) return a;
  return Bounds{Vec3{fminf(a.lo.x, b.lo.x), fminf(a.lo.y, b.lo.y), fminf(a.lo.z, b.lo.z)},
                Vec3{fmaxf(a.hi.x, b.hi.x), fmaxf(a.hi.y, b.hi.y), fmaxf(a.hi.z, b.hi.z)}, true};
}

}  // namespace

std::size_t buildGrid(FluidParticles& fluid, Grid& grid, const DomainParameters& domain) {
  const std::size_t n = fluid.count;
  Vec4* position = fluid.position.data();
  std::uint32_t* cell = fluid.cell.data();

  const Bounds bounds = backend::reduce(
      n, Bounds{Vec3{0, 0, 0}, Vec3{0, 0, 0}, false},
      SPH_LAMBDA(std::size_t i) {
        const Vec3 p = xyz(position[i]);
        return insideDomain(domain, p) ? Bounds{p, p, true} : Bounds{p, p, false};
      },
      SPH_LAMBDA(const Bounds& a, const Bounds& b) { return merge(a, b); });
  grid.spec = bounds.any ? makeGrid(bounds.lo, bounds.hi, grid.cellSize)
                         : makeGrid(domain.min, domain.min, grid.cellSize);
  const GridSpec spec = grid.spec;
  const std::uint32_t outsideBin = spec.cellCount;

  backend::forEach(
      n, SPH_LAMBDA(std::size_t i) {
        const Vec3 p = xyz(position[i]);
        cell[i] = insideDomain(domain, p)
                      ? cellIndex(spec, clampToGrid(spec, cellCoordinate(spec, p)))
                      : outsideBin;
      });

  grid.cellStart.resize(spec.cellCount + 2);
  backend::countingSort(cell, n, outsideBin + 1, fluid.order.data(), grid.cellStart.data());
  const std::size_t kept = grid.cellStart[outsideBin];

  backend::gather(fluid.position.data(), fluid.order.data(), kept, fluid.scratch4.data());
  fluid.position.swap(fluid.scratch4);
  backend::gather(fluid.velocity.data(), fluid.order.data(), kept, fluid.scratch4.data());
  fluid.velocity.swap(fluid.scratch4);
  backend::gather(fluid.id.data(), fluid.order.data(), kept, fluid.scratchId.data());
  fluid.id.swap(fluid.scratchId);

  fluid.count = kept;
  return n - kept;
}

}  // namespace sph::fluid
