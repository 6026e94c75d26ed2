// What the CPU's batched passes share: padded arrays, batch loads, the gather of packed
// neighbour records, lane masks, and the two walks over neighbours a SIMD batch at a time (8
// with AVX2): the fluid's listed neighbours and the walls'.
#pragma once

#if !defined(__CUDACC__)

#include <cstdint>
#include <initializer_list>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "backend/cpu_backend.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
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

SPH_BATCH_INLINE FloatBatch loadBatch(const float* a, std::uint32_t j) {
  return FloatBatch(a + j, stdx::element_aligned);
}

SPH_BATCH_INLINE BatchVec3 loadBatch(const float* x, const float* y, const float* z,
                                     std::uint32_t j) {
  return {loadBatch(x, j), loadBatch(y, j), loadBatch(z, j)};
}

#if defined(__AVX2__)
// Rows to columns: rows[k] holds 8 floats of one particle; after, rows[c] holds float c of the
// 8 particles.
SPH_BATCH_INLINE void transpose8(__m256 (&rows)[8]) {
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

#if defined(__AVX2__)
// The 4 floats of each record `at` names from `first` on, as 4 batches: records k and k + 4
// share a register, one in each half, so that the rows become columns by in-lane shuffles (8
// of them, against 24 for a whole 8 × 8 transpose).
SPH_BATCH_INLINE void transposeHalves(const float* records, const std::uint32_t* at,
                                      std::uint32_t first, __m256 (&columns)[4]) {
  __m256 rows[4];
  for (int k = 0; k < 4; ++k)
    rows[k] = _mm256_insertf128_ps(
        _mm256_castps128_ps256(_mm_loadu_ps(records + 8 * std::size_t(at[k]) + first)),
        _mm_loadu_ps(records + 8 * std::size_t(at[k + 4]) + first), 1);
  const __m256 t0 = _mm256_unpacklo_ps(rows[0], rows[1]), t1 = _mm256_unpacklo_ps(rows[2], rows[3]);
  const __m256 t2 = _mm256_unpackhi_ps(rows[0], rows[1]), t3 = _mm256_unpackhi_ps(rows[2], rows[3]);
  columns[0] = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(1, 0, 1, 0));
  columns[1] = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(3, 2, 3, 2));
  columns[2] = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(1, 0, 1, 0));
  columns[3] = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(3, 2, 3, 2));
}
#endif

// The first `kColumns` floats of each record `at` names, as batches: column c of the records in
// lane k. Always inlined, as the other batch helpers are: out of line, a pass's walk calls it
// for every batch of neighbours, and the force pass ran 1.7 times as long. A pass that reads only
// some of a record's floats gathers only those: the shuffles that turn rows into columns bound the
// solver's passes.
template <std::uint32_t kColumns = 8>
SPH_BATCH_INLINE void gatherRecords(const float* records, const std::uint32_t* at,
                                    FloatBatch (&columns)[8]) {
  static_assert(kColumns >= 1 && kColumns <= 8, "a record holds 8 floats");
#if defined(__AVX2__)
  if constexpr (kBatch == 8 && kColumns == 8) {
    __m256 rows[8];
    for (int k = 0; k < 8; ++k) rows[k] = _mm256_loadu_ps(records + 8 * std::size_t(at[k]));
    transpose8(rows);
    for (int c = 0; c < 8; ++c) columns[c] = FloatBatch(rows[c]);
    return;
  } else if constexpr (kBatch == 8 && kColumns <= 4) {
    __m256 low[4];
    transposeHalves(records, at, 0, low);
    for (std::uint32_t c = 0; c < kColumns; ++c) columns[c] = FloatBatch(low[c]);
    return;
  } else if constexpr (kBatch == 8) {
    __m256 low[4], high[4];
    transposeHalves(records, at, 0, low);
    transposeHalves(records, at, 4, high);
    for (std::uint32_t c = 0; c < 4; ++c) columns[c] = FloatBatch(low[c]);
    for (std::uint32_t c = 4; c < kColumns; ++c) columns[c] = FloatBatch(high[c - 4]);
    return;
  }
#endif
  for (std::uint32_t c = 0; c < kColumns; ++c)
    columns[c] = FloatBatch([&](auto lane) { return records[8 * std::size_t(at[lane]) + c]; });
}

// 0, 1, 2, ...: lane k of a load at j holds particle j + k.
SPH_BATCH_INLINE FloatBatch laneNumbers() {
  return FloatBatch([](auto k) { return float(k); });
}

// Bit k set for lane k of the mask.
SPH_BATCH_INLINE unsigned maskBits(const FloatBatch::mask_type& mask) {
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
SPH_BATCH_INLINE std::uint32_t appendLanes(std::uint32_t* out, std::uint32_t j, unsigned bits) {
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

// Visits particle i's fluid neighbours a batch at a time: listed(at), `at` pointing to a whole
// batch of the padded list; or, for a particle with too many to list, range(j, candidates) for
// the batch of the cells' particles from j on, `candidates` leaving out lanes past the row and
// i itself.
template <class Listed, class Range>
SPH_BATCH_INLINE void forEachNeighborBatch(const NeighborLists& lists, std::size_t i, Vec3 xi,
                                           Listed&& listed, Range&& range) {
  const std::uint32_t count = lists.count[i];
  if (count != kNeighborOverflow) {
    const std::uint32_t* list = lists.index + i * lists.stride;
    for (std::uint32_t k = 0; k < count; k += kBatch) listed(list + k);
    return;
  }
  const FloatBatch lane = laneNumbers();
  forEachNeighborRange(
      lists.spec, lists.cellStart, xi, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t j = begin; j < end; j += kBatch) {
          const FloatBatch offset = lane + FloatBatch(float(j)) - FloatBatch(float(i));
          range(j, lane < FloatBatch(float(end - j)) && offset != FloatBatch(0.0f));
        }
      });
}

// Visits the wall particles near x a batch at a time: visit(b, candidates), `candidates`
// leaving out lanes past the row.
template <class Visit>
SPH_BATCH_INLINE void forEachWallBatch(const WallCells& walls, Vec3 x, Visit&& visit) {
  if (walls.cellStart == nullptr || !nearGrid(walls.spec, x)) return;
  const FloatBatch lane = laneNumbers();
  forEachNeighborRange(walls.spec, walls.cellStart, x, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t b = begin; b < end; b += kBatch) visit(b, lane < FloatBatch(float(end - b)));
  });
}

// What a batched pass reads of boundary particles (walls, or objects' surfaces): their cells and
// their positions and volumes as columns. Pointers, so that a pass's lambda copies it.
struct BoundaryBatches {
  WallCells cells;
  const float* x;
  const float* y;
  const float* z;
  const float* volume;
};

inline BoundaryBatches boundaryBatches(const BoundaryParticles<CpuBackend>& boundary) {
  return {wallCells(boundary), boundary.batchX.data(), boundary.batchY.data(),
          boundary.batchZ.data(), boundary.batchVolume.data()};
}

// The boundary particles within reach of x_i, a batch at a time: visit(pair, volume, b) for each
// batch with one in reach, `pair` their separation from x_i (none at x_i itself), `volume`
// theirs.
template <class Visit>
SPH_BATCH_INLINE void forEachBoundaryPairBatch(const BoundaryBatches& boundary, Vec3 x,
                                               const BatchVec3& xi, float h2, Visit&& visit) {
  const FloatBatch h2Batch(h2), zero(0.0f);
  forEachWallBatch(boundary.cells, x,
                   [&](std::uint32_t b, const FloatBatch::mask_type& candidates) {
                     const BatchVec3 rib = xi - loadBatch(boundary.x, boundary.y, boundary.z, b);
                     const FloatBatch r2 = dot(rib, rib);
                     const auto near = candidates && r2 < h2Batch && r2 > zero;
                     if (stdx::none_of(near)) return;
                     visit(makePair(rib, r2, near, h2), loadBatch(boundary.volume, b), b);
                   });
}

}  // namespace sph::fluid::detail

#endif  // !__CUDACC__
