// The density pass on the CPU with neighbours taken a SIMD batch at a time (8 with AVX2) over
// the contiguous rows of cells: the same formulas as density_pressure.hpp (core/kernels.hpp,
// core/eos.hpp), and for each particle the same neighbours in the same order on any thread
// count. It also splits what the batched force pass reads into padded arrays, and lists each
// particle's neighbours for it.
#pragma once

#if !defined(__CUDACC__)

#include <cstdint>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "backend/cpu_backend.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/parameters.hpp"
#include "fluid/particles.hpp"
#include "sph/core/eos.hpp"
#include "sph/core/momentum.hpp"
#include "sph/core/select.hpp"

namespace sph::fluid::detail {

using CpuBackend = backend::CpuBackend;
constexpr std::size_t kBatch = FloatBatch::size();
static_assert(kBatch <= kBatchPadding, "the padded arrays must hold a batch load at their end");

// Sizes each array to n + padding, the padding filled with `padding`.
inline void padArrays(std::size_t n, float padding,
                      std::initializer_list<backend::Buffer<float>*> arrays) {
  for (backend::Buffer<float>* a : arrays) {
    a->resize(n + kBatchPadding);
    for (std::size_t k = n; k < n + kBatchPadding; ++k) (*a)[k] = padding;
  }
}

inline FloatBatch loadBatch(const float* a, std::uint32_t j) {
  return FloatBatch(a + j, stdx::element_aligned);
}

inline BatchVec3 loadBatch(const float* x, const float* y, const float* z, std::uint32_t j) {
  return {loadBatch(x, j), loadBatch(y, j), loadBatch(z, j)};
}

#if defined(__AVX2__)
// Rows to columns: rows[k] holds 8 floats of one particle; after, rows[c] holds float c of the
// 8 particles.
inline void transpose8(__m256 (&rows)[8]) {
  const __m256 t0 = _mm256_unpacklo_ps(rows[0], rows[1]), t1 = _mm256_unpackhi_ps(rows[0], rows[1]);
  const __m256 t2 = _mm256_unpacklo_ps(rows[2], rows[3]), t3 = _mm256_unpackhi_ps(rows[2], rows[3]);
  const __m256 t4 = _mm256_unpacklo_ps(rows[4], rows[5]), t5 = _mm256_unpackhi_ps(rows[4], rows[5]);
  const __m256 t6 = _mm256_unpacklo_ps(rows[6], rows[7]), t7 = _mm256_unpackhi_ps(rows[6], rows[7]);
  const __m256 s0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 s1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 s2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 s3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 s4 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 s5 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 s6 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 s7 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(3, 2, 3, 2));
  rows[0] = _mm256_permute2f128_ps(s0, s4, 0x20);
  rows[1] = _mm256_permute2f128_ps(s1, s5, 0x20);
  rows[2] = _mm256_permute2f128_ps(s2, s6, 0x20);
  rows[3] = _mm256_permute2f128_ps(s3, s7, 0x20);
  rows[4] = _mm256_permute2f128_ps(s0, s4, 0x31);
  rows[5] = _mm256_permute2f128_ps(s1, s5, 0x31);
  rows[6] = _mm256_permute2f128_ps(s2, s6, 0x31);
  rows[7] = _mm256_permute2f128_ps(s3, s7, 0x31);
}
#endif

// The 8 floats of each record `at` names, as 8 batches: column c of the records in lane k.
inline void gatherRecords(const float* records, const std::uint32_t* at, FloatBatch (&columns)[8]) {
#if defined(__AVX2__)
  if constexpr (kBatch == 8) {
    __m256 rows[8];
    for (int k = 0; k < 8; ++k) rows[k] = _mm256_loadu_ps(records + 8 * std::size_t(at[k]));
    transpose8(rows);
    for (int c = 0; c < 8; ++c) columns[c] = FloatBatch(rows[c]);
    return;
  }
#endif
  for (int c = 0; c < 8; ++c)
    columns[c] = FloatBatch([&](auto lane) { return records[8 * std::size_t(at[lane]) + c]; });
}

// 0, 1, 2, ...: lane k of a load at j holds particle j + k.
inline FloatBatch laneNumbers() {
  return FloatBatch([](auto k) { return float(k); });
}

// Bit k set for lane k of the mask.
inline unsigned maskBits(const FloatBatch::mask_type& mask) {
  FloatBatch sign(0.0f);
  stdx::where(mask, sign) = FloatBatch(-1.0f);
#if defined(__AVX2__)
  if constexpr (kBatch == 8) return unsigned(_mm256_movemask_ps(static_cast<__m256>(sign)));
#endif
  unsigned bits = 0;
  for (std::size_t k = 0; k < kBatch; ++k) bits |= (sign[k] < 0.0f ? 1u : 0u) << k;
  return bits;
}

// Writes j + k for each lane k set in `bits`, in order, from `out` on; returns how many. May
// write a whole batch past them: `out` needs room for kBatch more.
inline std::uint32_t appendLanes(std::uint32_t* out, std::uint32_t j, unsigned bits) {
#if defined(__AVX2__)
  if constexpr (kBatch == 8) {
    // For each 8-bit mask the lanes set, packed to the front (AVX2 has no compress).
    static const auto packing = [] {
      struct Table {
        alignas(32) std::int32_t lanes[256][8];
      } table{};
      for (unsigned mask = 0; mask < 256; ++mask) {
        int count = 0;
        for (int lane = 0; lane < 8; ++lane)
          if (mask & (1u << lane)) table.lanes[mask][count++] = lane;
      }
      return table;
    }();
    const __m256i lanes = _mm256_load_si256(reinterpret_cast<const __m256i*>(packing.lanes[bits]));
    const __m256i indices = _mm256_add_epi32(_mm256_set1_epi32(int(j)), lanes);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), indices);
    return std::uint32_t(__builtin_popcount(bits));
  }
#endif
  std::uint32_t count = 0;
  for (; bits != 0; bits &= bits - 1) out[count++] = j + std::uint32_t(__builtin_ctz(bits));
  return count;
}

// A particle's neighbour list is padded to a whole number of batches with the index of the
// first padding element (n), whose position is far away: a batch gathered from the list needs
// no count of its own.
constexpr std::uint32_t kMaxListed = 256;  // more neighbours than this: none listed

inline std::uint32_t paddedLength(std::uint32_t count) {
  return (count + std::uint32_t(kBatch) - 1) / std::uint32_t(kBatch) * std::uint32_t(kBatch);
}

template <class Kernels>
void densityPassBatched(FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                        const BoundaryParticles<CpuBackend>& boundary,
                        const FluidParameters& params, Kernels kernels) {
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
  const GridSpec wallGrid = boundary.grid;
  const std::uint32_t* wallCellStart = boundary.cellStart.data();
  const float* wx = boundary.batchX.data();
  const float* wy = boundary.batchY.data();
  const float* wz = boundary.batchZ.data();
  const float* wv = boundary.batchVolume.data();
  float* density = fluid.density.data();
  float* pressure = fluid.pressure.data();
  Vec4* state = fluid.pressureState.data();
  float* stateA = fluid.batchPOverRho2.data();
  float* stateC = fluid.batchPressure.data();
  float* stateD = fluid.batchDensity.data();
  const FluidParameters p = params;
  const FloatBatch h2(params.h * params.h);
  const std::uint32_t stride = fluid.neighborStride;
  std::uint32_t* neighbors = fluid.neighbors.data();
  std::uint32_t* neighborCount = fluid.neighborCount.data();
  const std::uint32_t padding = std::uint32_t(n);

  CpuBackend::forEach(n, [=](std::size_t i) {
    const FloatBatch lane = laneNumbers();
    const BatchVec3 xi = broadcast(Vec3{x[i], y[i], z[i]});
    // Seed 1 eq. 4, self included; walls count with mass ρ0 ψ_b (Akinci et al. 2012 eq. 6).
    FloatBatch sum(0.0f), wallSum(0.0f);
    // The neighbours (self excluded) for the force pass, in the order found: gathered here,
    // where a batch may be written past the last, then copied to the particle's list.
    std::uint32_t found[kMaxListed + kBatchPadding];
    std::uint32_t count = 0;
    // One batch of candidates from j on: the density sum, and the neighbours appended to the
    // list. No branch on whether any lane passed: it would be mispredicted often, and
    // appending none costs a store.
    const auto scan = [&](std::uint32_t j, const FloatBatch::mask_type& candidates)
                          SPH_BATCH_INLINE_LAMBDA {
                            const BatchVec3 rij = xi - loadBatch(x, y, z, j);
                            const FloatBatch r2 = dot(rij, rij);
                            auto near = candidates && r2 < h2;
                            sum += kernels.W(select(near, r2, h2));
                            // The particle itself is in one batch of one row: a scalar test finds
                            // that batch.
                            if (j <= i && i < j + kBatch)
                              near = near && lane != FloatBatch(float(i - j));
                            const unsigned bits = maskBits(near);
                            if (count <= kMaxListed)
                              count += appendLanes(found + count, j, bits);
                            else
                              count += std::uint32_t(__builtin_popcount(bits));
                          };
    forEachNeighborRange(spec, cellStart, Vec3{x[i], y[i], z[i]},
                         [&](std::uint32_t begin, std::uint32_t end) {
                           for (std::uint32_t j = begin; j < end; j += kBatch)
                             scan(j, lane < FloatBatch(float(end - j)));
                         });
    std::uint32_t* list = neighbors + i * stride;
    if (count <= kMaxListed && paddedLength(count) <= stride) {
      for (std::uint32_t k = 0; k < count; ++k) list[k] = found[k];
      for (std::uint32_t k = count; k < paddedLength(count); ++k) list[k] = padding;
      neighborCount[i] = count;
    } else {
      neighborCount[i] = kNeighborOverflow;  // the force pass searches the cells
    }
    if (wallCellStart != nullptr) {
      forEachNeighborRange(wallGrid, wallCellStart, Vec3{x[i], y[i], z[i]},
                           [&](std::uint32_t begin, std::uint32_t end) {
                             for (std::uint32_t b = begin; b < end; b += kBatch) {
                               const BatchVec3 rib = xi - loadBatch(wx, wy, wz, b);
                               const FloatBatch r2 = dot(rib, rib);
                               const auto near = lane < FloatBatch(float(end - b)) && r2 < h2;
                               wallSum += loadBatch(wv, b) * kernels.W(select(near, r2, h2));
                             }
                           });
    }
    const float rho = p.mass * stdx::reduce(sum) + p.restDensity * stdx::reduce(wallSum);
    const float pi =
        pressureFromDensity(p.eos, rho, p.restDensity, p.stiffness, p.clampNegativePressure);
    density[i] = rho;
    pressure[i] = pi;
    const Vec4 s{pressureOverDensitySquared(pi, rho), 1.0f / rho, pi, rho};
    state[i] = s;
    stateA[i] = s.x;
    stateC[i] = s.z;
    stateD[i] = s.w;
  });
}

}  // namespace sph::fluid::detail

#endif  // !__CUDACC__
