// The density pass on the CPU, a SIMD batch of candidates at a time over the contiguous rows of
// cells: the same sums as density_pressure.hpp (pair_terms.hpp), and for each particle the same
// neighbours in the same order on any thread count. It also lists each particle's neighbours
// for the passes after it, and splits what the batched force pass reads into padded arrays.
#pragma once

#if !defined(__CUDACC__)

#include <cstdint>
#include <type_traits>
#include <utility>

#include "fluid/batches.hpp"
#include "fluid/pair_terms.hpp"

namespace sph::fluid::detail {

template <class Kernels>
void densityPassBatched(FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                        const BoundaryParticles<CpuBackend>& boundary,
                        const BoundaryParticles<CpuBackend>& objects, const FluidParameters& params,
                        Kernels kernels) {
  const std::size_t n = fluid.count;
  // Far away: the padding never passes a distance test.
  padArrays(n, 1e30f, {&fluid.batchX, &fluid.batchY, &fluid.batchZ});
  // No pressure, and a density to divide by: padding lanes, far away, add exactly nothing.
  padArrays(n, 0.0f, {&fluid.batchPOverRho2, &fluid.batchPressure});
  padArrays(n, 1.0f, {&fluid.batchDensity});
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
  float* density = fluid.density.data();
  float* pressure = fluid.pressure.data();
  Vec4* state = fluid.pressureState.data();
  float* stateA = fluid.batchPOverRho2.data();
  float* stateC = fluid.batchPressure.data();
  float* stateD = fluid.batchDensity.data();
  const FluidParameters p = params;
  const bool integrated = fluid.densityIsState;
  const FloatBatch h2(params.h * params.h);
  const std::uint32_t stride = fluid.neighborStride;
  std::uint32_t* neighbors = fluid.neighbors.data();
  std::uint32_t* neighborCount = fluid.neighborCount.data();
  const std::uint32_t padding = std::uint32_t(n);

  CpuBackend::forEach(n, [=](std::size_t i) {
    const FloatBatch lane = laneNumbers();
    const Vec3 xs{x[i], y[i], z[i]};
    const BatchVec3 xi = broadcast(xs);
    // The neighbours (self excluded) for the force pass, in the order found: gathered here,
    // where a batch may be written past the last, then copied to the particle's list.
    std::uint32_t found[kMaxListed + kBatchPadding];
    // Meteer 2011, eq. 4, the particle itself included: the sum and the number of neighbours
    // found. A separation is taken to its nearest image only near a periodic face, decided
    // once a particle; each walk keeps its sums to itself, so that the common one, away from
    // the faces, holds them in registers.
    const auto walk = [&](auto wrap) SPH_BATCH_INLINE_LAMBDA {
      FloatBatch sum(0.0f);
      std::uint32_t count = 0;
      // One batch of candidates from j on: the density sum, and the neighbours appended to
      // the list. No branch on whether any lane passed: it would be mispredicted often, and
      // appending none costs a store.
      const auto rows = [&](std::uint32_t begin, std::uint32_t end) SPH_BATCH_INLINE_LAMBDA {
        for (std::uint32_t j = begin; j < end; j += kBatch) {
          BatchVec3 rij = xi - loadBatch(x, y, z, j);
          if constexpr (decltype(wrap)::value) rij = minimumImage(p.periodic, rij);
          const FloatBatch r2 = dot(rij, rij);
          auto near = lane < FloatBatch(float(end - j)) && r2 < h2;
          sum += kernelWhere(kernels, r2, near);
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
      return std::pair<FloatBatch, std::uint32_t>(sum, count);
    };
    const auto [sum, count] =
        nearSeam(p.periodic, xs) ? walk(std::true_type{}) : walk(std::false_type{});
    FloatBatch wallSum(0.0f);
    std::uint32_t* list = neighbors + i * stride;
    if (count <= kMaxListed && paddedLength(count) <= stride) {
      for (std::uint32_t k = 0; k < count; ++k) list[k] = found[k];
      for (std::uint32_t k = count; k < paddedLength(count); ++k) list[k] = padding;
      neighborCount[i] = count;
    } else {
      neighborCount[i] = kNeighborOverflow;  // the passes after this search the cells
    }
    forEachWallBatch(
        walls.cells, xs, [&](std::uint32_t b, const FloatBatch::mask_type& candidates) {
          const BatchVec3 rib = xi - loadBatch(walls.x, walls.y, walls.z, b);
          const FloatBatch r2 = dot(rib, rib);
          wallSum += loadBatch(walls.volume, b) * kernelWhere(kernels, r2, candidates && r2 < h2);
        });
    forEachWallBatch(
        objectWalls.cells, xs, [&](std::uint32_t b, const FloatBatch::mask_type& candidates) {
          const BatchVec3 rib = xi - loadBatch(objectWalls.x, objectWalls.y, objectWalls.z, b);
          const FloatBatch r2 = dot(rib, rib);
          wallSum +=
              loadBatch(objectWalls.volume, b) * kernelWhere(kernels, r2, candidates && r2 < h2);
        });
    const PressureState s = pressureStateFromDensity(
        integrated
            ? keptDensity(density[i], densityFromSums(sumLanes(sum), sumLanes(wallSum), p), p)
            : densityFromSums(sumLanes(sum), sumLanes(wallSum), p),
        p);
    density[i] = s.density;
    pressure[i] = s.pressure;
    state[i] = packed(s);
    stateA[i] = s.pOverRho2;
    stateC[i] = s.pressure;
    stateD[i] = s.density;
  });
}

}  // namespace sph::fluid::detail

#endif  // !__CUDACC__
