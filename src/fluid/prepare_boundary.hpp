// Stage (once, at set-up): the walls' grid, their particles sorted by its cells, and each
// one's volume ψ_b. Prepared on the host with the CPU primitives, then handed to backend B.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "fluid/parameters.hpp"
#include "fluid/particles.hpp"

namespace sph::fluid {

// The CPU's SIMD passes: the boundary particles' positions and volumes (xyz, w, sorted) as four
// padded arrays. Nothing on the GPU.
template <class B>
void uploadBatchArrays(BoundaryParticles<B>& boundary, const std::vector<Vec4>& position) {
  if constexpr (B::kBatches) {
    const std::size_t n = position.size();
    // Far away, with no volume: the padding never passes a distance test.
    std::vector<float> x(n + kBatchPadding, 1e30f), y(x), z(x), v(n + kBatchPadding, 0.0f);
    for (std::size_t k = 0; k < n; ++k) {
      x[k] = position[k].x;
      y[k] = position[k].y;
      z[k] = position[k].z;
      v[k] = position[k].w;
    }
    B::upload(boundary.batchX, x.data(), x.size());
    B::upload(boundary.batchY, y.data(), y.size());
    B::upload(boundary.batchZ, z.data(), z.size());
    B::upload(boundary.batchVolume, v.data(), v.size());
  }
}

template <class B>
void prepareBoundary(BoundaryParticles<B>& boundary, const std::vector<Vec3>& points,
                     std::uint32_t firstId, const FluidParameters& params) {
  const std::size_t n = points.size();
  boundary.count = n;
  if (n == 0) return;
  Vec3 lo = points[0], hi = lo;
  for (const Vec3& p : points) {
    lo = Vec3{fminf(lo.x, p.x), fminf(lo.y, p.y), fminf(lo.z, p.z)};
    hi = Vec3{fmaxf(hi.x, p.x), fmaxf(hi.y, p.y), fmaxf(hi.z, p.z)};
  }
  const Vec3 margin{params.h, params.h, params.h};
  boundary.grid = makeGrid(lo - margin, hi + margin, params.h);
  const GridSpec grid = boundary.grid;
  std::vector<std::uint32_t> cell(n), order(n), cellStart(grid.cellCount + 1);
  for (std::size_t i = 0; i < n; ++i)
    cell[i] = cellIndex(grid, clampToGrid(grid, cellCoordinate(grid, points[i])));
  backend::countingSort(cell.data(), n, grid.cellCount, order.data(), cellStart.data());

  // Walls are sampled on the fluid's lattice, so each wall particle stands for one lattice
  // cell: ψ_b = m / ρ0, and a fluid particle at rest against a wall reads exactly ρ0. Akinci's
  // ψ_b = 1 / Σ_k W_bk (eq. 4) counts only wall neighbours, so at the wall's surface it
  // overestimates the volume: +4.5 % density next to a two-layer wall at h = 2d, which the
  // stiffness of a weakly compressible fluid turns into a pressure many times ρ g H.
  const float volume = params.mass / params.restDensity;
  std::vector<Vec4> position(n);
  std::vector<std::uint32_t> id(n);
  for (std::size_t k = 0; k < n; ++k) {
    position[k] = makeVec4(points[order[k]], volume);
    id[k] = firstId + order[k];
  }
  B::upload(boundary.position, position.data(), n);
  B::upload(boundary.id, id.data(), n);
  B::upload(boundary.cellStart, cellStart.data(), cellStart.size());
  uploadBatchArrays(boundary, position);
}

}  // namespace sph::fluid
