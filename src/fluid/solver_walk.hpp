// How the incompressible solver's passes walk a particle's neighbours: through the neighbour
// lists of the density pass (the cells for a particle with too many), reading each neighbour
// from 8-float records (particles.hpp), one neighbour at a time (the GPU, and the CPU's
// reference) or a SIMD batch at a time (the CPU). A pass is a struct with
//   kFirstOfStep                            true: computes the listed pairs' kernel gradients
//                                           and keeps them; false: reads them back
//   kWalls                                  whether it walks the walls
//   kColumns                                how many of a neighbour's record's floats it reads:
//                                           the first kColumns (the walks gather no more)
//   Sum start<S, V>(i)                      what particle i sums, zeroed
//   addFluid(sum, ∇W_ij, columns)           a fluid neighbour: columns[c] is float c of its record
//   addWall(sum, ∇W_ib, volume)             a wall particle of volume ψ_b, if kWalls
//   addMovingWall(sum, ∇W_ib, volume, v_b)  an object's particle as a boundary, if kWalls
//   finish(i, sum)                          writes particle i's result
// with S, V = float, Vec3 or FloatBatch, BatchVec3: the pass is written once for both walks.
//
// Positions do not change within a step, and neither does ∇W_ij = g_ij (x_i - x_j): the step's
// first pass keeps g_ij beside each listed neighbour (pairGradient), and every later pass reads
// it back instead of a square root and a division a pair, where the lists are small enough for
// that to pay (dfsph_solve.hpp).
#pragma once

#include <cstdint>

#include "fluid/batches.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

// ∇W for a pair the lists do not hold a gradient for.
template <class S, class V, class M, class Kernels>
SPH_HD_INLINE V pairGradient(const Kernels& kernels, const Pair<S, V, M>& pair) {
  return pair.rij * pair.where(kernels.gradFactor(pair.r));
}

template <class B, class Kernels, class Pass>
void solverPass(const FluidParticles<B>& fluid, const Grid<B>& grid,
                const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                const float* records, Kernels kernels, Periodicity periodic, Pass pass,
                float* keptGradients) {
  const NeighborLists lists = neighborLists(fluid, grid);
  const WallCells walls = wallCells(boundary);
  const Vec4* wall = boundary.position.data();  // w: volume ψ_b
  const WallCells objectCells = wallCells(objects);
  const Vec4* object = objects.position.data();
  const Vec4* objectVelocity = objects.velocity.data();
  const float h2 = kernels.h2;
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const float* ri = records + kRecordFields * i;
        const Vec3 xi{ri[0], ri[1], ri[2]};
        const bool seam = nearSeam(periodic, xi);
        // Named here, not first inside `if constexpr`: nvcc's device lambdas may not capture
        // there.
        (void)walls;
        (void)wall;
        (void)objectCells;
        (void)object;
        (void)objectVelocity;
        (void)keptGradients;
        auto sum = pass.template start<float, Vec3>(i);
        // Neighbour j's record and x_i - x_j.
        const auto read = [&](std::uint32_t j, float(&columns)[kRecordFields]) {
          const float* rj = records + kRecordFields * j;
          for (std::uint32_t c = 0; c < Pass::kColumns; ++c) columns[c] = readOnly(rj + c);
          return separation(periodic, seam, xi, Vec3{columns[0], columns[1], columns[2]});
        };
        const std::uint32_t count = lists.count[i];
        if (count != kNeighborOverflow) {
          const std::uint32_t* list = lists.index + i * lists.stride;
          float* kept = keptGradients != nullptr ? keptGradients + i * lists.stride : nullptr;
          for (std::uint32_t k = 0; k < count; ++k) {
            float columns[kRecordFields];
            const Vec3 rij = read(readOnly(list + k), columns);
            float g;
            if (Pass::kFirstOfStep || kept == nullptr) {
              const float r2 = lengthSquared(rij);
              const auto pair = makePair(rij, r2, r2 < h2, h2);
              g = pair.where(kernels.gradFactor(pair.r));
              if (Pass::kFirstOfStep && kept != nullptr) kept[k] = g;
            } else {
              g = kept[k];
            }
            pass.addFluid(sum, rij * g, columns);
          }
        } else {
          forEachNeighbor(lists.spec, lists.cellStart, xi, [&](std::uint32_t j) {
            if (j == i) return;
            float columns[kRecordFields];
            const Vec3 rij = read(j, columns);
            const float r2 = lengthSquared(rij);
            if (r2 >= h2) return;
            pass.addFluid(sum, pairGradient(kernels, makePair(rij, r2, true, h2)), columns);
          });
        }
        if constexpr (Pass::kWalls) {
          forEachWallNeighbor(walls, xi, [&](std::uint32_t b) {
            const Vec4 xb = readOnly(wall + b);
            const Vec3 rib = xi - xyz(xb);
            const float r2 = lengthSquared(rib);
            if (r2 >= h2 || r2 <= 0.0f) return;
            pass.addWall(sum, pairGradient(kernels, makePair(rib, r2, true, h2)), xb.w);
          });
          forEachWallNeighbor(objectCells, xi, [&](std::uint32_t k) {
            const Vec4 xk = readOnly(object + k);
            const Vec3 rik = xi - xyz(xk);
            const float r2 = lengthSquared(rik);
            if (r2 >= h2 || r2 <= 0.0f) return;
            pass.addMovingWall(sum, pairGradient(kernels, makePair(rik, r2, true, h2)), xk.w,
                               xyz(readOnly(objectVelocity + k)));
          });
        }
        pass.finish(i, sum);
      });
}

#if !defined(__CUDACC__)

namespace detail {

template <class Kernels, class Pass>
void solverPassBatched(const FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                       const BoundaryParticles<CpuBackend>& boundary,
                       const BoundaryParticles<CpuBackend>& objects, const float* records,
                       Kernels kernels, Periodicity periodic, Pass pass, float* keptGradients) {
  const NeighborLists lists = neighborLists(fluid, grid);
  const BoundaryBatches walls = boundaryBatches(boundary);
  const BoundaryBatches objectWalls = boundaryBatches(objects);
  const Vec4* objectVelocity = objects.velocity.data();  // padded with zeros
  const float h2 = kernels.h2;
  const FloatBatch h2Batch(h2), zero(0.0f);
  CpuBackend::forEach(fluid.count, [=](std::size_t i) {
    const float* ri = records + kRecordFields * i;
    const Vec3 xs{ri[0], ri[1], ri[2]};
    const BatchVec3 xi = broadcast(xs);
    const bool seam = nearSeam(periodic, xs);
    auto sum = pass.template start<FloatBatch, BatchVec3>(i);
    // A batch of the cells' particles: only those within h count.
    const auto search = [&](const FloatBatch(&columns)[kRecordFields],
                            const FloatBatch::mask_type& candidates) SPH_BATCH_INLINE_LAMBDA {
      const BatchVec3 rij =
          separation(periodic, seam, xi, BatchVec3{columns[0], columns[1], columns[2]});
      const FloatBatch r2 = dot(rij, rij);
      const auto near = candidates && r2 < h2Batch;
      if (stdx::none_of(near)) return;
      pass.addFluid(sum, pairGradient(kernels, makePair(rij, r2, near, h2)), columns);
    };
    const std::uint32_t* list = lists.index + i * lists.stride;
    float* kept = keptGradients != nullptr ? keptGradients + i * lists.stride : nullptr;
    forEachNeighborBatch(
        lists, i, xs,
        [&](const std::uint32_t* at) SPH_BATCH_INLINE_LAMBDA {
          FloatBatch columns[kRecordFields];
          gatherRecords<Pass::kColumns>(records, at, columns);
          const BatchVec3 rij =
              separation(periodic, seam, xi, BatchVec3{columns[0], columns[1], columns[2]});
          FloatBatch g;
          if (Pass::kFirstOfStep || kept == nullptr) {
            const FloatBatch r2 = dot(rij, rij);
            const auto pair = makePair(rij, r2, r2 < h2Batch, h2);
            g = pair.where(kernels.gradFactor(pair.r));
            if (Pass::kFirstOfStep && kept != nullptr)
              g.copy_to(kept + (at - list), stdx::element_aligned);
          } else {
            g = loadBatch(kept + (at - list), 0);
          }
          pass.addFluid(sum, rij * g, columns);
        },
        [&](std::uint32_t j, const FloatBatch::mask_type& candidates) {
          std::uint32_t at[kBatch];
          for (std::uint32_t k = 0; k < kBatch; ++k) at[k] = j + k;  // the padding is a record
          FloatBatch columns[kRecordFields];
          gatherRecords<Pass::kColumns>(records, at, columns);
          search(columns, candidates);
        });
    if constexpr (Pass::kWalls) {
      forEachBoundaryPairBatch(walls, xs, xi, h2,
                               [&](const auto& pair, FloatBatch volume, std::uint32_t) {
                                 pass.addWall(sum, pairGradient(kernels, pair), volume);
                               });
      forEachBoundaryPairBatch(
          objectWalls, xs, xi, h2, [&](const auto& pair, FloatBatch volume, std::uint32_t k) {
            const BatchVec3 vk{FloatBatch([&](auto lane) { return objectVelocity[k + lane].x; }),
                               FloatBatch([&](auto lane) { return objectVelocity[k + lane].y; }),
                               FloatBatch([&](auto lane) { return objectVelocity[k + lane].z; })};
            pass.addMovingWall(sum, pairGradient(kernels, pair), volume, vk);
          });
    }
    pass.finish(i, sum);
  });
}

}  // namespace detail

#endif  // !__CUDACC__

// The pass over every particle, on the walk the engine chose; keptGradients: the listed pairs'
// g_ij (n × neighborStride), written by a first pass of the step, read by the others; null:
// every pass computes them.
template <class B, class Kernels, class Pass>
void runSolverPass(const FluidParticles<B>& fluid, const Grid<B>& grid,
                   const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                   const float* records, Kernels kernels, const Periodicity& periodic,
                   [[maybe_unused]] NeighborWalk walk, const Pass& pass, float* keptGradients) {
#if !defined(__CUDACC__)
  if constexpr (B::kBatches) {
    if (walk == NeighborWalk::Batched) {
      detail::solverPassBatched(fluid, grid, boundary, objects, records, kernels, periodic, pass,
                                keptGradients);
      return;
    }
  }
#endif
  solverPass(fluid, grid, boundary, objects, records, kernels, periodic, pass, keptGradients);
}

}  // namespace sph::fluid
