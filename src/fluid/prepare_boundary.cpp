#include <cmath>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/stages.hpp"

namespace sph::fluid {

void prepareBoundary(BoundaryParticles& boundary, const FluidParameters& params) {
  const std::size_t n = boundary.count;
  if (n == 0) return;
  Vec3 lo = xyz(boundary.position[0]), hi = lo;
  for (std::size_t i = 1; i < n; ++i) {
    const Vec3 p = xyz(boundary.position[i]);
    lo = Vec3{fminf(lo.x, p.x), fminf(lo.y, p.y), fminf(lo.z, p.z)};
    hi = Vec3{fmaxf(hi.x, p.x), fmaxf(hi.y, p.y), fmaxf(hi.z, p.z)};
  }
  const Vec3 margin{params.h, params.h, params.h};
  boundary.grid = makeGrid(lo - margin, hi + margin, params.h);
  const GridSpec grid = boundary.grid;
  Buffer<std::uint32_t> cell(n), order(n);
  for (std::size_t i = 0; i < n; ++i) {
    cell[i] = cellIndex(grid, clampToGrid(grid, cellCoordinate(grid, xyz(boundary.position[i]))));
  }
  boundary.cellStart.resize(grid.cellCount + 1);
  backend::countingSort(cell.data(), n, grid.cellCount, order.data(), boundary.cellStart.data());
  Buffer<Vec4> position(n);
  Buffer<std::uint32_t> id(n);
  backend::gather(boundary.position.data(), order.data(), n, position.data());
  backend::gather(boundary.id.data(), order.data(), n, id.data());
  boundary.position.swap(position);
  boundary.id.swap(id);

  // Akinci et al. 2012 eq. 4: ψ_b = 1 / Σ_k W_bk over wall neighbours, so a dense or a sparse
  // wall contributes the same density.
  withKernels(params, [&](auto kernels) {
    const std::uint32_t* cellStart = boundary.cellStart.data();
    Vec4* wall = boundary.position.data();
    std::vector<float> volume(n);
    float* out = volume.data();
    backend::forEach(n, [=](std::size_t b) {
      const Vec3 xb = xyz(wall[b]);
      float sum = 0.0f;
      forEachNeighbor(grid, cellStart, xb, [&](std::uint32_t k) {
        sum += kernels.W(lengthSquared(xb - xyz(wall[k])));
      });
      out[b] = 1.0f / sum;
    });
    for (std::size_t b = 0; b < n; ++b) wall[b].w = volume[b];
  });
}

}  // namespace sph::fluid
