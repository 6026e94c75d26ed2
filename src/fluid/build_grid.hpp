// Stage: build the uniform grid. Reads position, velocity, id, the solver's warm start and the
// density where it is state (continuity).
// Writes them reordered by cell, grid.cellStart and count. Particles outside the domain or in
// an outlet are removed; returns how many.
#pragma once

#include <cmath>
#include <cstddef>

#include "fluid/parameters.hpp"
#include "fluid/particles.hpp"

namespace sph::fluid {

namespace detail {

SPH_HD bool insideBox(Vec3 lo, Vec3 hi, Vec3 p) {
  // Written so that NaN compares as outside.
  return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
}

// The outlet p is in, or outlets.count.
SPH_HD std::uint32_t outletOf(const Outlets& outlets, Vec3 p) {
  for (std::uint32_t k = 0; k < outlets.count; ++k)
    if (insideBox(outlets.min[k], outlets.max[k], p)) return k;
  return outlets.count;
}

SPH_HD bool kept(const DomainParameters& d, Vec3 p) {
  return insideBox(d.min, d.max, p) && outletOf(d.outlets, p) == d.outlets.count;
}

// Particles in each outlet.
struct OutletCounts {
  std::uint32_t n[kOutletSlots];
};

SPH_HD OutletCounts addCounts(const OutletCounts& a, const OutletCounts& b) {
  OutletCounts sum;
  for (std::uint32_t k = 0; k < kOutletSlots; ++k) sum.n[k] = a.n[k] + b.n[k];
  return sum;
}

// The extent of the particles inside the domain.
struct Bounds {
  Vec3 lo, hi;
  bool any;
};

SPH_HD Bounds merge(const Bounds& a, const Bounds& b) {
  if (!a.any) return b;
  if (!b.any) return a;
  // Comparisons, not fminf: the positions here are inside the domain, so never NaN, and g++
  // calls the library for fminf.
  const auto lower = [](float u, float v) { return u < v ? u : v; };
  const auto higher = [](float u, float v) { return u > v ? u : v; };
  return Bounds{Vec3{lower(a.lo.x, b.lo.x), lower(a.lo.y, b.lo.y), lower(a.lo.z, b.lo.z)},
                Vec3{higher(a.hi.x, b.hi.x), higher(a.hi.y, b.hi.y), higher(a.hi.z, b.hi.z)}, true};
}

// Each cell's particles in id order (a distributed run's ghost bit aside): an insertion sort of
// each cell's slice of `order`, a few particles each.
template <class B>
void orderCellsById(FluidParticles<B>& fluid, const Grid<B>& grid) {
  const std::uint32_t* id = fluid.id.data();
  std::uint32_t* order = fluid.order.data();
  const std::uint32_t* start = grid.cellStart.data();
  B::forEach(
      grid.spec.cellCount, SPH_LAMBDA(std::size_t c) {
        const std::uint32_t first = start[c], end = start[c + 1];
        for (std::uint32_t k = first + 1; k < end; ++k) {
          const std::uint32_t row = order[k];
          const std::uint32_t key = id[row] & ~kGhostBit;
          std::uint32_t j = k;
          for (; j > first && (id[order[j - 1]] & ~kGhostBit) > key; --j) order[j] = order[j - 1];
          order[j] = row;
        }
      });
}

}  // namespace detail

// How many particles each outlet holds now (buildGrid removes them).
template <class B>
detail::OutletCounts countInOutlets(const FluidParticles<B>& fluid, const Outlets& outlets) {
  const Vec4* position = fluid.position.data();
  const Outlets o = outlets;
  return B::reduce(
      fluid.count, detail::OutletCounts{},
      SPH_LAMBDA(std::size_t i) {
        detail::OutletCounts one{};
        const std::uint32_t k = detail::outletOf(o, xyz(position[i]));
        if (k < o.count) one.n[k] = 1;
        return one;
      },
      SPH_LAMBDA(const detail::OutletCounts& a, const detail::OutletCounts& b) {
        return detail::addCounts(a, b);
      });
}

template <class B>
std::size_t buildGrid(FluidParticles<B>& fluid, Grid<B>& grid, const DomainParameters& domain) {
  const std::size_t n = fluid.count;
  Vec4* position = fluid.position.data();
  std::uint32_t* cell = fluid.cell.data();

  const detail::Bounds bounds = B::reduce(
      n, detail::Bounds{Vec3{0, 0, 0}, Vec3{0, 0, 0}, false},
      SPH_LAMBDA(std::size_t i) {
        const Vec3 p = xyz(position[i]);
        return detail::Bounds{p, p, detail::kept(domain, p)};
      },
      SPH_LAMBDA(const detail::Bounds& a, const detail::Bounds& b) { return detail::merge(a, b); });
  const Periodicity& periodic = domain.periodic;
  const Vec3 lo = grid.shared ? grid.sharedLo : bounds.lo;
  const Vec3 hi = grid.shared ? grid.sharedHi : bounds.hi;
  grid.spec = bounds.any
                  ? makePeriodicGrid(lo, hi, grid.cellSize, periodic.axes, periodic.lo, periodic.hi)
                  : makeGrid(domain.min, domain.min, grid.cellSize);
  const GridSpec spec = grid.spec;
  const std::uint32_t outsideBin = spec.cellCount;

  B::forEach(
      n, SPH_LAMBDA(std::size_t i) {
        const Vec3 p = xyz(position[i]);
        cell[i] = detail::kept(domain, p)
                      ? cellIndex(spec, clampToGrid(spec, cellCoordinate(spec, p)))
                      : outsideBin;
      });

  grid.cellStart.resize(spec.cellCount + 2);
  B::countingSort(cell, n, outsideBin + 1, fluid.order.data(), grid.cellStart.data(),
                  grid.sortScratch);
  const std::size_t kept = B::read(grid.cellStart.data() + outsideBin);
  if (grid.shared) detail::orderCellsById(fluid, grid);

  B::gather(fluid.position.data(), fluid.order.data(), kept, fluid.scratch4.data());
  fluid.position.swap(fluid.scratch4);
  B::gather(fluid.velocity.data(), fluid.order.data(), kept, fluid.scratch4.data());
  fluid.velocity.swap(fluid.scratch4);
  B::gather(fluid.id.data(), fluid.order.data(), kept, fluid.scratchId.data());
  fluid.id.swap(fluid.scratchId);
  if (fluid.densityIsState) {
    B::gather(fluid.density.data(), fluid.order.data(), kept, fluid.scratchDensity.data());
    fluid.density.swap(fluid.scratchDensity);
  }
  if (fluid.warmStart.size() != 0) {
    B::gather(fluid.warmStart.data(), fluid.order.data(), kept, fluid.scratch4.data());
    fluid.warmStart.swap(fluid.scratch4);
  }

  fluid.count = kept;
  return n - kept;
}

}  // namespace sph::fluid
