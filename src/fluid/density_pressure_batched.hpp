// The density pass on the CPU with neighbours taken a SIMD batch at a time (8 with AVX2) over
// the contiguous rows of cells: the same formulas as density_pressure.hpp (core/kernels.hpp,
// core/eos.hpp), and for each particle the same neighbours in the same order on any thread
// count. It also splits what the batched force pass reads into padded arrays.
#pragma once

#if !defined(__CUDACC__)

#include <cstdint>

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

// 0, 1, 2, ...: lane k of a load at j holds particle j + k.
inline FloatBatch laneNumbers() {
  return FloatBatch([](auto k) { return float(k); });
}

template <class Kernels>
void densityPassBatched(FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                        const BoundaryParticles<CpuBackend>& boundary,
                        const FluidParameters& params, Kernels kernels) {
  const std::size_t n = fluid.count;
  // Far away: the padding never passes a distance test.
  padArrays(n, 1e30f, {&fluid.batchX, &fluid.batchY, &fluid.batchZ});
  padArrays(n, 0.0f,
            {&fluid.batchPOverRho2, &fluid.batchInverseDensity, &fluid.batchPressure,
             &fluid.batchDensity});
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
  float* stateB = fluid.batchInverseDensity.data();
  float* stateC = fluid.batchPressure.data();
  float* stateD = fluid.batchDensity.data();
  const FluidParameters p = params;
  const FloatBatch h2(params.h * params.h);

  CpuBackend::forEach(n, [=](std::size_t i) {
    const FloatBatch lane = laneNumbers();
    const BatchVec3 xi = broadcast(Vec3{x[i], y[i], z[i]});
    // Seed 1 eq. 4, self included; walls count with mass ρ0 ψ_b (Akinci et al. 2012 eq. 6).
    FloatBatch sum(0.0f), wallSum(0.0f);
    forEachNeighborRange(spec, cellStart, Vec3{x[i], y[i], z[i]},
                         [&](std::uint32_t begin, std::uint32_t end) {
                           for (std::uint32_t j = begin; j < end; j += kBatch) {
                             const BatchVec3 rij = xi - loadBatch(x, y, z, j);
                             const FloatBatch r2 = dot(rij, rij);
                             const auto near = lane < FloatBatch(float(end - j)) && r2 < h2;
                             sum += kernels.W(select(near, r2, h2));
                           }
                         });
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
    stateB[i] = s.y;
    stateC[i] = s.z;
    stateD[i] = s.w;
  });
}

}  // namespace sph::fluid::detail

#endif  // !__CUDACC__
