// The one walk of the passes that read a particle's neighbours after the density pass: the
// forces, the continuity density and the incompressible solver's passes. A distributed run's
// ghosts (particles.hpp) are neighbours here and never walked themselves: their owners compute
// them, the density pass included. It walks the neighbour
// lists of the density pass (the cells for a particle with too many), reading each neighbour
// from 8-float records (particles.hpp), one neighbour at a time (the GPU, and the CPU's
// reference) or a SIMD batch at a time (the CPU). A pass is a struct with
//   kGradients      true: the pass is given each pair's kernel gradient ∇W (the solver's
//                   passes); false: the pair itself (Pair, pair_terms.hpp), for a pass that
//                   reads more of it than the gradient
//   kFirstOfStep    with kGradients: true computes the listed pairs' gradients and keeps them,
//                   false reads them back
//   kSkipsCoincident  pairs of fluid particles at one point left out (with kGradients: false)
//   kWalls, kObjects  whether it walks the walls, and the objects' particles as a boundary
//   kColumns        how many of a neighbour's record's floats it reads: the first kColumns
//   Sum start<S, V>(i)                       what particle i sums, zeroed
//   addFluid(sum, pair, columns)             a fluid neighbour: columns[c] is float c of its
//                                            record; `pair` is ∇W_ij with kGradients
//   addWall(sum, pair, volume)               a wall particle of volume ψ_b, if kWalls
//   addMovingWall(sum, pair, volume, v_b)    an object's particle, if kObjects
//   finish(i, sum)                           writes particle i's result
// with S, V = float, Vec3 or FloatBatch, BatchVec3: a pass is written once for both walks.
//
// Positions do not change within a step, and neither does ∇W_ij = g_ij (x_i - x_j): the
// solver's first pass of a step keeps g_ij beside each listed neighbour, and its later passes
// read it back instead of a square root and a division a pair, where the lists are small
// enough for that to pay (dfsph_solve.hpp).
#pragma once

#include <cstdint>
#include <type_traits>
#include <utility>

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

// What a pass is handed for a pair within reach: its gradient, or the pair.
template <class Pass, class Kernels, class S, class V, class M>
SPH_HD_INLINE auto pairFor(const Kernels& kernels, const Pair<S, V, M>& pair) {
  if constexpr (Pass::kGradients)
    return pairGradient(kernels, pair);
  else
    return pair;
}

namespace detail {

template <class B, class Kernels, class Pass>
void walkOneAtATime(const FluidParticles<B>& fluid, const Grid<B>& grid,
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
  const std::uint32_t* id = fluid.id.data();
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        if (isGhost(id[i])) return;  // its owner computes it
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
        // A fluid neighbour not among the listed gradients: within reach, and apart.
        const auto visit = [&](const Vec3& rij, const float(&columns)[kRecordFields]) {
          const float r2 = lengthSquared(rij);
          if (r2 >= h2) return;
          if constexpr (!Pass::kGradients && Pass::kSkipsCoincident)
            if (r2 <= 0.0f) return;
          pass.addFluid(sum, pairFor<Pass>(kernels, makePair(rij, r2, true, h2)), columns);
        };
        const std::uint32_t count = lists.count[i];
        if (count != kNeighborOverflow) {
          const std::uint32_t* list = lists.index + i * lists.stride;
          float* kept = keptGradients != nullptr ? keptGradients + i * lists.stride : nullptr;
          for (std::uint32_t k = 0; k < count; ++k) {
            float columns[kRecordFields];
            const Vec3 rij = read(readOnly(list + k), columns);
            if constexpr (Pass::kGradients) {
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
            } else {
              visit(rij, columns);
            }
          }
        } else {
          forEachNeighbor(lists.spec, lists.cellStart, xi, [&](std::uint32_t j) {
            if (j == i) return;
            float columns[kRecordFields];
            visit(read(j, columns), columns);
          });
        }
        if constexpr (Pass::kWalls) {
          forEachWallNeighbor(walls, xi, [&](std::uint32_t b) {
            const Vec4 xb = readOnly(wall + b);
            const Vec3 rib = xi - xyz(xb);
            const float r2 = lengthSquared(rib);
            if (r2 >= h2 || r2 <= 0.0f) return;
            pass.addWall(sum, pairFor<Pass>(kernels, makePair(rib, r2, true, h2)), xb.w);
          });
        }
        if constexpr (Pass::kObjects) {
          forEachWallNeighbor(objectCells, xi, [&](std::uint32_t k) {
            const Vec4 xk = readOnly(object + k);
            const Vec3 rik = xi - xyz(xk);
            const float r2 = lengthSquared(rik);
            if (r2 >= h2 || r2 <= 0.0f) return;
            pass.addMovingWall(sum, pairFor<Pass>(kernels, makePair(rik, r2, true, h2)), xk.w,
                               xyz(readOnly(objectVelocity + k)));
          });
        }
        pass.finish(i, sum);
      });
}

#if !defined(__CUDACC__)

template <class Kernels, class Pass>
void walkBatched(const FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                 const BoundaryParticles<CpuBackend>& boundary,
                 const BoundaryParticles<CpuBackend>& objects, const float* records,
                 Kernels kernels, Periodicity periodic, Pass pass, float* keptGradients) {
  const NeighborLists lists = neighborLists(fluid, grid);
  const BoundaryBatches walls = boundaryBatches(boundary);
  const BoundaryBatches objectWalls = boundaryBatches(objects);
  const Vec4* objectVelocity = objects.velocity.data();  // padded with zeros
  const float h2 = kernels.h2;
  const FloatBatch h2Batch(h2), zero(0.0f);
  const std::uint32_t* id = fluid.id.data();
  CpuBackend::forEach(fluid.count, [=](std::size_t i) {
    if (isGhost(id[i])) return;  // its owner computes it
    const float* ri = records + kRecordFields * i;
    const Vec3 xs{ri[0], ri[1], ri[2]};
    const BatchVec3 xi = broadcast(xs);
    const bool seam = nearSeam(periodic, xs);
    auto sum = pass.template start<FloatBatch, BatchVec3>(i);
    // A batch of neighbours, `candidates` those that may be: only those within h (and apart,
    // for a pass that skips coincident pairs) count.
    const auto visit = [&](const FloatBatch(&columns)[kRecordFields],
                           const FloatBatch::mask_type& candidates) SPH_BATCH_INLINE_LAMBDA {
      const BatchVec3 rij =
          separation(periodic, seam, xi, BatchVec3{columns[0], columns[1], columns[2]});
      const FloatBatch r2 = dot(rij, rij);
      auto near = candidates && r2 < h2Batch;
      if constexpr (!Pass::kGradients && Pass::kSkipsCoincident) near = near && r2 > zero;
      if (stdx::none_of(near)) return;
      pass.addFluid(sum, pairFor<Pass>(kernels, makePair(rij, r2, near, h2)), columns);
    };
    const std::uint32_t* list = lists.index + i * lists.stride;
    float* kept = keptGradients != nullptr ? keptGradients + i * lists.stride : nullptr;
    forEachNeighborBatch(
        lists, i, xs,
        [&](const std::uint32_t* at) SPH_BATCH_INLINE_LAMBDA {
          FloatBatch columns[kRecordFields];
          gatherRecords<Pass::kColumns>(records, at, columns);
          if constexpr (Pass::kGradients) {
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
          } else {
            visit(columns, FloatBatch::mask_type(true));
          }
        },
        [&](std::uint32_t j, const FloatBatch::mask_type& candidates) {
          std::uint32_t at[kBatch];
          for (std::uint32_t k = 0; k < kBatch; ++k) at[k] = j + k;  // the padding is a record
          FloatBatch columns[kRecordFields];
          gatherRecords<Pass::kColumns>(records, at, columns);
          visit(columns, candidates);
        });
    if constexpr (Pass::kWalls) {
      forEachBoundaryPairBatch(walls, xs, xi, h2,
                               [&](const auto& pair, FloatBatch volume, std::uint32_t) {
                                 pass.addWall(sum, pairFor<Pass>(kernels, pair), volume);
                               });
    }
    if constexpr (Pass::kObjects) {
      forEachBoundaryPairBatch(
          objectWalls, xs, xi, h2, [&](const auto& pair, FloatBatch volume, std::uint32_t k) {
            const BatchVec3 vk{FloatBatch([&](auto lane) { return objectVelocity[k + lane].x; }),
                               FloatBatch([&](auto lane) { return objectVelocity[k + lane].y; }),
                               FloatBatch([&](auto lane) { return objectVelocity[k + lane].z; })};
            pass.addMovingWall(sum, pairFor<Pass>(kernels, pair), volume, vk);
          });
    }
    pass.finish(i, sum);
  });
}

#endif  // !__CUDACC__

}  // namespace detail

namespace detail {

template <class B, class Pass>
void searchOneAtATime(FluidParticles<B>& fluid, const Grid<B>& grid,
                      const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                      float h2, Periodicity periodic, Pass pass) {
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const WallCells walls = wallCells(boundary);
  const WallCells objectCells = wallCells(objects);
  const Vec4* position = fluid.position.data();
  const Vec4* wall = boundary.position.data();
  const Vec4* object = objects.position.data();
  const std::uint32_t stride = fluid.neighborStride;
  std::uint32_t* neighbors = fluid.neighbors.data();
  std::uint32_t* neighborCount = fluid.neighborCount.data();
  const std::uint32_t* id = fluid.id.data();
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        // A ghost's owner computes it; it lists no neighbours, so no pass walks stale rows.
        if (isGhost(id[i])) {
          neighborCount[i] = 0;
          return;
        }
        const Vec3 xi = xyz(position[i]);
        const bool seam = nearSeam(periodic, xi);
        auto sum = pass.template start<float>(i);
        std::uint32_t* list = neighbors + i * stride;
        std::uint32_t count = 0;
        forEachNeighbor(spec, cellStart, xi, [&](std::uint32_t j) {
          const float r2 =
              lengthSquared(separation(periodic, seam, xi, xyz(readOnly(position + j))));
          if (r2 >= h2) return;
          pass.addFluid(sum, r2, true);
          if (j != i && count < stride) list[count] = j;
          if (j != i) ++count;
        });
        neighborCount[i] = count <= stride ? count : kNeighborOverflow;
        // The walls' particles, then the objects': both are boundary to the density.
        const auto addBoundary = [&](const WallCells& cells, const Vec4* boundaryPosition) {
          forEachWallNeighbor(cells, xi, [&](std::uint32_t b) {
            const Vec4 xb = readOnly(boundaryPosition + b);
            pass.addWall(sum, lengthSquared(xi - xyz(xb)), true, xb.w);
          });
        };
        addBoundary(walls, wall);
        addBoundary(objectCells, object);
        pass.finish(i, sum);
      });
}

#if !defined(__CUDACC__)

// A SIMD batch of candidates at a time over the contiguous rows of cells, reading positions as
// three padded arrays: for each particle the same neighbours in the same order on any thread
// count.
template <class Pass>
void searchBatched(FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                   const BoundaryParticles<CpuBackend>& boundary,
                   const BoundaryParticles<CpuBackend>& objects, float h2Scalar,
                   Periodicity periodic, Pass pass) {
  const std::size_t n = fluid.count;
  // Far away: the padding never passes a distance test.
  padArrays(n, 1e30f, {&fluid.batchX, &fluid.batchY, &fluid.batchZ});
  float* x = fluid.batchX.data();
  float* y = fluid.batchY.data();
  float* z = fluid.batchZ.data();
  const Vec4* position = fluid.position.data();
  CpuBackend::forEach(n, [=](std::size_t i) {
    x[i] = position[i].x;
    y[i] = position[i].y;
    z[i] = position[i].z;
  });

  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const BoundaryBatches walls = boundaryBatches(boundary);
  const BoundaryBatches objectWalls = boundaryBatches(objects);
  const FloatBatch h2(h2Scalar);
  const std::uint32_t stride = fluid.neighborStride;
  std::uint32_t* neighbors = fluid.neighbors.data();
  std::uint32_t* neighborCount = fluid.neighborCount.data();
  const std::uint32_t padding = std::uint32_t(n);
  const std::uint32_t* id = fluid.id.data();

  CpuBackend::forEach(n, [=](std::size_t i) {
    // A ghost's owner computes it; it lists no neighbours, so no pass walks stale rows.
    if (isGhost(id[i])) {
      neighborCount[i] = 0;
      return;
    }
    const FloatBatch lane = laneNumbers();
    const Vec3 xs{x[i], y[i], z[i]};
    const BatchVec3 xi = broadcast(xs);
    // The neighbours (self excluded) in the order found: gathered here, where a batch may be
    // written past the last, then copied to the particle's list.
    std::uint32_t found[kMaxListed + kBatchPadding];
    // A separation is taken to its nearest image only near a periodic face, decided once a
    // particle; each walk keeps its sum to itself, so that the common one, away from the
    // faces, holds it in registers.
    const auto walk = [&](auto wrap) SPH_BATCH_INLINE_LAMBDA {
      auto sum = pass.template start<FloatBatch>(i);
      std::uint32_t count = 0;
      // One batch of candidates from j on: the pass's sum, and the neighbours appended to the
      // list. No branch on whether any lane passed: it would be mispredicted often, and
      // appending none costs a store.
      const auto rows = [&](std::uint32_t begin, std::uint32_t end) SPH_BATCH_INLINE_LAMBDA {
        for (std::uint32_t j = begin; j < end; j += kBatch) {
          BatchVec3 rij = xi - loadBatch(x, y, z, j);
          if constexpr (decltype(wrap)::value) rij = minimumImage(periodic, rij);
          const FloatBatch r2 = dot(rij, rij);
          auto near = lane < FloatBatch(float(end - j)) && r2 < h2;
          pass.addFluid(sum, r2, near);
          // The particle itself is in one batch of one row: a scalar test finds that batch.
          if (j <= i && i < j + kBatch) near = near && lane != FloatBatch(float(i - j));
          const unsigned bits = maskBits(near);
          if (count <= kMaxListed)
            count += appendLanes(found + count, j, bits);
          else
            count += std::uint32_t(__builtin_popcount(bits));
        }
      };
      if constexpr (decltype(wrap)::value)
        forEachNeighborRange(spec, cellStart, xs, rows);
      else
        forEachNeighborRangeAwayFromSeams(spec, cellStart, xs, rows);
      return std::make_pair(sum, count);
    };
    auto walked = nearSeam(periodic, xs) ? walk(std::true_type{}) : walk(std::false_type{});
    auto& sum = walked.first;
    const std::uint32_t count = walked.second;
    std::uint32_t* list = neighbors + i * stride;
    if (count <= kMaxListed && paddedLength(count) <= stride) {
      for (std::uint32_t k = 0; k < count; ++k) list[k] = found[k];
      for (std::uint32_t k = count; k < paddedLength(count); ++k) list[k] = padding;
      neighborCount[i] = count;
    } else {
      neighborCount[i] = kNeighborOverflow;  // the passes after this search the cells
    }
    for (const BoundaryBatches* boundaryParticles : {&walls, &objectWalls}) {
      const BoundaryBatches& b = *boundaryParticles;
      forEachWallBatch(b.cells, xs, [&](std::uint32_t k, const FloatBatch::mask_type& candidates) {
        const BatchVec3 rib = xi - loadBatch(b.x, b.y, b.z, k);
        const FloatBatch r2 = dot(rib, rib);
        pass.addWall(sum, r2, candidates && r2 < h2, loadBatch(b.volume, k));
      });
    }
    pass.finish(i, sum);
  });
}

#endif  // !__CUDACC__

}  // namespace detail

// The density pass's walk: every particle of the 27 cells around each particle, itself
// included, handed to the pass by its squared distance where it is within reach
// (addFluid(sum, r2, near)), and so the walls' and the objects' particles (addWall(sum, r2, near,
// volume)); Sum start<S>(i) and finish(i, sum) as above. It lists each particle's neighbours,
// itself left out, for the passes after it (neighborCount kNeighborOverflow: too many to list).
template <class B, class Pass>
void searchAndList(FluidParticles<B>& fluid, const Grid<B>& grid,
                   const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                   float h, const Periodicity& periodic, [[maybe_unused]] NeighborWalk walk,
                   const Pass& pass) {
#if !defined(__CUDACC__)
  if constexpr (B::kBatches) {
    if (walk == NeighborWalk::Batched) {
      detail::searchBatched(fluid, grid, boundary, objects, h * h, periodic, pass);
      return;
    }
  }
#endif
  detail::searchOneAtATime(fluid, grid, boundary, objects, h * h, periodic, pass);
}

// The pass over every particle, on the walk the engine chose. `records`: 8 floats a particle
// (n + kBatchPadding of them, the padding's far away). keptGradients: with kGradients, the
// listed pairs' g_ij (n × neighborStride), written by a first pass of the step, read by the
// others; null: every pass computes them.
template <class B, class Kernels, class Pass>
void runPass(const FluidParticles<B>& fluid, const Grid<B>& grid,
             const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
             const float* records, Kernels kernels, const Periodicity& periodic,
             [[maybe_unused]] NeighborWalk walk, const Pass& pass, float* keptGradients = nullptr) {
#if !defined(__CUDACC__)
  if constexpr (B::kBatches) {
    if (walk == NeighborWalk::Batched) {
      detail::walkBatched(fluid, grid, boundary, objects, records, kernels, periodic, pass,
                          keptGradients);
      return;
    }
  }
#endif
  detail::walkOneAtATime(fluid, grid, boundary, objects, records, kernels, periodic, pass,
                         keptGradients);
}

}  // namespace sph::fluid
