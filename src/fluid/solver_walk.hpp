// How the incompressible solver's passes walk a particle's neighbours: through the neighbour
// lists of the density pass (the cells for a particle with too many), reading each neighbour
// from 8-float records (particles.hpp), one neighbour at a time (the GPU, and the CPU's
// reference) or a SIMD batch at a time (the CPU). A pass is a struct with
//   Sum start<S, V>(i)                      what particle i sums, zeroed
//   addFluid(sum, pair, columns)            a fluid neighbour: columns[c] is float c of its record
//   addWall(sum, pair, volume)              a wall particle of volume ψ_b, if kWalls
//   finish(i, sum)                          writes particle i's result
// with S, V = float, Vec3 or FloatBatch, BatchVec3: the pass is written once for both walks.
#pragma once

#include <cstdint>

#include "fluid/batches.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

template <class B, class Pass>
void solverPass(const FluidParticles<B>& fluid, const Grid<B>& grid,
                const BoundaryParticles<B>& boundary, const float* records, float h, Pass pass) {
  const NeighborLists lists = neighborLists(fluid, grid);
  const WallCells walls = wallCells(boundary);
  const Vec4* wall = boundary.position.data();  // w: volume ψ_b
  const float h2 = h * h;
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const float* ri = records + kRecordFields * i;
        const Vec3 xi{ri[0], ri[1], ri[2]};
        // Named here, not first inside `if constexpr`: nvcc's device lambdas may not capture
        // there.
        (void)walls;
        (void)wall;
        auto sum = pass.template start<float, Vec3>(i);
        forEachListedNeighbor(lists, i, xi, [&](std::uint32_t j) {
          const float* rj = records + kRecordFields * j;
          float columns[kRecordFields];
          for (std::uint32_t c = 0; c < kRecordFields; ++c) columns[c] = readOnly(rj + c);
          const Vec3 rij = xi - Vec3{columns[0], columns[1], columns[2]};
          const float r2 = lengthSquared(rij);
          if (r2 >= h2) return;
          pass.addFluid(sum, makePair(rij, r2, true, h2), columns);
        });
        if constexpr (Pass::kWalls) {
          forEachWallNeighbor(walls, xi, [&](std::uint32_t b) {
            const Vec4 xb = readOnly(wall + b);
            const Vec3 rib = xi - xyz(xb);
            const float r2 = lengthSquared(rib);
            if (r2 >= h2 || r2 <= 0.0f) return;
            pass.addWall(sum, makePair(rib, r2, true, h2), xb.w);
          });
        }
        pass.finish(i, sum);
      });
}

#if !defined(__CUDACC__)

namespace detail {

template <class Pass>
void solverPassBatched(const FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                       const BoundaryParticles<CpuBackend>& boundary, const float* records, float h,
                       Pass pass) {
  const NeighborLists lists = neighborLists(fluid, grid);
  const WallCells walls = wallCells(boundary);
  const float* wx = boundary.batchX.data();
  const float* wy = boundary.batchY.data();
  const float* wz = boundary.batchZ.data();
  const float* wv = boundary.batchVolume.data();
  const float h2 = h * h;
  const FloatBatch h2Batch(h2), zero(0.0f);
  CpuBackend::forEach(fluid.count, [=](std::size_t i) {
    const float* ri = records + kRecordFields * i;
    const Vec3 xs{ri[0], ri[1], ri[2]};
    const BatchVec3 xi = broadcast(xs);
    auto sum = pass.template start<FloatBatch, BatchVec3>(i);
    const auto add = [&](const FloatBatch(&columns)[kRecordFields],
                         const FloatBatch::mask_type& candidates) SPH_BATCH_INLINE_LAMBDA {
      const BatchVec3 rij = xi - BatchVec3{columns[0], columns[1], columns[2]};
      const FloatBatch r2 = dot(rij, rij);
      const auto near = candidates && r2 < h2Batch;
      if (stdx::none_of(near)) return;
      pass.addFluid(sum, makePair(rij, r2, near, h2), columns);
    };
    forEachNeighborBatch(
        lists, i, xs,
        [&](const std::uint32_t* at) SPH_BATCH_INLINE_LAMBDA {
          FloatBatch columns[kRecordFields];
          gatherRecords(records, at, columns);
          add(columns, FloatBatch::mask_type(true));
        },
        [&](std::uint32_t j, const FloatBatch::mask_type& candidates) {
          std::uint32_t at[kBatch];
          for (std::uint32_t k = 0; k < kBatch; ++k) at[k] = j + k;  // the padding is a record
          FloatBatch columns[kRecordFields];
          gatherRecords(records, at, columns);
          add(columns, candidates);
        });
    if constexpr (Pass::kWalls) {
      forEachWallBatch(walls, xs, [&](std::uint32_t b, const FloatBatch::mask_type& candidates) {
        const BatchVec3 rib = xi - loadBatch(wx, wy, wz, b);
        const FloatBatch r2 = dot(rib, rib);
        const auto near = candidates && r2 < h2Batch && r2 > zero;
        if (stdx::none_of(near)) return;
        pass.addWall(sum, makePair(rib, r2, near, h2), loadBatch(wv, b));
      });
    }
    pass.finish(i, sum);
  });
}

}  // namespace detail

#endif  // !__CUDACC__

// The pass over every particle, on the walk the engine chose.
template <class B, class Pass>
void runSolverPass(const FluidParticles<B>& fluid, const Grid<B>& grid,
                   const BoundaryParticles<B>& boundary, const float* records, float h,
                   [[maybe_unused]] NeighborWalk walk, const Pass& pass) {
#if !defined(__CUDACC__)
  if constexpr (B::kBatches) {
    if (walk == NeighborWalk::Batched) {
      detail::solverPassBatched(fluid, grid, boundary, records, h, pass);
      return;
    }
  }
#endif
  solverPass(fluid, grid, boundary, records, h, pass);
}

}  // namespace sph::fluid
