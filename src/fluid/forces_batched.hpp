// The force pass on the CPU, a SIMD batch of neighbours at a time: gathered from the lists the
// batched density pass made (padded to whole batches), or, for a particle with too many
// neighbours to list, loaded from the contiguous rows of cells. The same formulas as forces.hpp
// (core/momentum.hpp, core/kernels.hpp, written once for a float and for a batch); lanes that
// are not neighbours get zero kernel factors. As there, the colour field only for surface
// tension.
#pragma once

#if !defined(__CUDACC__)

#include "fluid/density_pressure_batched.hpp"

namespace sph::fluid::detail {

template <class Options, class Kernels>
void forcePassBatched(FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                      const BoundaryParticles<CpuBackend>& boundary, const FluidParameters& params,
                      Kernels kernels) {
  constexpr bool kSymmetric = Options::form == PressureForm::Symmetric;
  constexpr bool kArtificial = Options::viscosity == ViscosityModel::Artificial;
  const std::size_t n = fluid.count;
  padArrays(n, 0.0f, {&fluid.batchVX, &fluid.batchVY, &fluid.batchVZ});
  float* vx = fluid.batchVX.data();
  float* vy = fluid.batchVY.data();
  float* vz = fluid.batchVZ.data();
  const Vec4* velocity = fluid.velocity.data();
  // Records: the padding far away (never within reach), with no pressure or velocity and a
  // density of 1 to divide by.
  fluid.batchRecords.resize(8 * (n + kBatchPadding));
  float* records = fluid.batchRecords.data();
  const float* pressureTermSource =
      kSymmetric ? fluid.batchPOverRho2.data() : fluid.batchPressure.data();
  const float* densitySource = fluid.batchDensity.data();
  const float* px = fluid.batchX.data();
  const float* py = fluid.batchY.data();
  const float* pz = fluid.batchZ.data();
  CpuBackend::forEach(n + kBatchPadding, [=](std::size_t i) {
    const bool real = i < n;
    if (real) {
      vx[i] = velocity[i].x;
      vy[i] = velocity[i].y;
      vz[i] = velocity[i].z;
    }
    float* r = records + 8 * i;
    r[0] = px[i];
    r[1] = py[i];
    r[2] = pz[i];
    r[3] = pressureTermSource[i];
    r[4] = real ? velocity[i].x : 0.0f;
    r[5] = real ? velocity[i].y : 0.0f;
    r[6] = real ? velocity[i].z : 0.0f;
    r[7] = densitySource[i];
  });

  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const GridSpec wallGrid = boundary.grid;
  const std::uint32_t* wallCellStart = boundary.cellStart.data();
  const float* x = fluid.batchX.data();
  const float* y = fluid.batchY.data();
  const float* z = fluid.batchZ.data();
  // What the pressure term reads of a neighbour: p/ρ² (symmetric form) or p (the paper's).
  const float* pressureTermJ =
      kSymmetric ? fluid.batchPOverRho2.data() : fluid.batchPressure.data();
  const float* density = fluid.batchDensity.data();
  const float* wx = boundary.batchX.data();
  const float* wy = boundary.batchY.data();
  const float* wz = boundary.batchZ.data();
  const float* wv = boundary.batchVolume.data();
  const Vec4* state = fluid.pressureState.data();
  Vec4* acceleration = fluid.acceleration.data();
  const std::uint32_t* id = fluid.id.data();
  const std::uint32_t stride = fluid.neighborStride;
  const std::uint32_t* neighbors = fluid.neighbors.data();
  const std::uint32_t* neighborCount = fluid.neighborCount.data();
  const Vec4* external = fluid.externalById.size() ? fluid.externalById.data() : nullptr;
  const FluidParameters p = params;
  const FloatBatch h2(p.h * p.h), zero(0.0f);
  const FloatBatch mass(p.mass), viscosity(p.viscosity), soundSpeed(p.soundSpeed), h(p.h);
  const FloatBatch restDensity(p.restDensity), wallFriction(p.wallFriction);
  const BatchVec3 gravity = broadcast(p.gravity);

  CpuBackend::forEach(n, [=](std::size_t i) {
    const Vec3 xs{x[i], y[i], z[i]};
    const BatchVec3 xi = broadcast(xs);
    const BatchVec3 vi = broadcast(Vec3{vx[i], vy[i], vz[i]});
    const Vec4 si = state[i];
    const FloatBatch pOverRho2I(si.x), inverseDensityI(si.y), pI(si.z), rhoI(si.w);
    BatchVec3 a{zero, zero, zero}, colourGradient{zero, zero, zero};
    FloatBatch colourLaplacian(0.0f);

    // The pair terms of a batch of fluid neighbours; lanes off `candidates`, or out of reach,
    // add nothing.
    // 1/ρ_j only where a formula reads it: the paper's pressure form, surface tension.
    constexpr bool kReadsInverseDensity = !kSymmetric || Options::surfaceTension;
    const auto addPairs = [&](const BatchVec3& xj, const BatchVec3& vj,
                              const FloatBatch& pressureTerm, const FloatBatch& rhoJ,
                              const FloatBatch::mask_type& candidates) SPH_BATCH_INLINE_LAMBDA {
      FloatBatch inverseDensityJ(0.0f);
      if constexpr (kReadsInverseDensity) inverseDensityJ = FloatBatch(1.0f) / rhoJ;
      const BatchVec3 rij = xi - xj;
      const FloatBatch r2 = dot(rij, rij);
      const auto near = candidates && r2 < h2;
      if (stdx::none_of(near)) return;
      const FloatBatch r = realSqrt(select(near, r2, h2));
      const BatchVec3 gradW = rij * select(near, kernels.gradFactor(r), zero);
      if constexpr (kSymmetric) {
        a += pressureAccelerationSymmetric(mass, pOverRho2I, pressureTerm, gradW);
      } else {
        a += pressureAccelerationPaper(mass, pI, inverseDensityI, pressureTerm, inverseDensityJ,
                                       gradW);
      }
      const BatchVec3 vij = vi - vj;
      if constexpr (kArtificial) {
        a += artificialViscosityAcceleration(viscosity, soundSpeed, h, mass, rhoI, rhoJ, vij, rij,
                                             select(near, r2, h2), gradW);
      } else {
        a += mullerViscosityAcceleration(viscosity, mass, rhoI, rhoJ, vij,
                                         select(near, kernels.laplacian(r), zero));
      }
      if constexpr (Options::surfaceTension) {
        const FloatBatch volumeJ = mass * inverseDensityJ;  // seed 1 eqs. 11-12, C_j = 1
        colourGradient += rij * (volumeJ * select(near, kernels.colourGradFactor(r), zero));
        colourLaplacian += volumeJ * select(near, kernels.colourLaplacian(r), zero);
      }
    };

    const std::uint32_t count = neighborCount[i];
    if (count != kNeighborOverflow) {
      const std::uint32_t* list = neighbors + i * stride;
      for (std::uint32_t k = 0; k < count; k += kBatch) {
        const std::uint32_t* at = list + k;  // padded: whole batches
        FloatBatch c[8];
        gatherRecords(records, at, c);
        addPairs({c[0], c[1], c[2]}, {c[4], c[5], c[6]}, c[3], c[7], FloatBatch::mask_type(true));
      }
    } else {
      const FloatBatch lane = laneNumbers();
      forEachNeighborRange(spec, cellStart, xs, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t j = begin; j < end; j += kBatch) {
          const FloatBatch offset = lane + FloatBatch(float(j)) - FloatBatch(float(i));
          addPairs(loadBatch(x, y, z, j), loadBatch(vx, vy, vz, j), loadBatch(pressureTermJ, j),
                   loadBatch(density, j), lane < FloatBatch(float(end - j)) && offset != zero);
        }
      });
    }

    if (wallCellStart != nullptr) {
      const FloatBatch lane = laneNumbers();
      forEachNeighborRange(
          wallGrid, wallCellStart, xs, [&](std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t b = begin; b < end; b += kBatch) {
              const BatchVec3 rib = xi - loadBatch(wx, wy, wz, b);
              const FloatBatch r2 = dot(rib, rib);
              const auto near = lane < FloatBatch(float(end - b)) && r2 < h2 && r2 > zero;
              if (stdx::none_of(near)) continue;
              const FloatBatch r = realSqrt(select(near, r2, h2));
              const FloatBatch volumeB = loadBatch(wv, b);
              const FloatBatch massB = restDensity * volumeB;
              const BatchVec3 gradW = rib * select(near, kernels.gradFactor(r), zero);
              const FloatBatch pB = wallPressure(pI, rhoI, gravity, -rib, p.clampNegativePressure);
              a += boundaryPressureAcceleration(massB, pI, rhoI, pB, gradW);
              if (p.wallFriction > 0.0f) {
                const BatchVec3 friction =
                    kArtificial
                        ? artificialViscosityAcceleration(viscosity, soundSpeed, h, massB, rhoI,
                                                          restDensity, vi, rib,
                                                          select(near, r2, h2), gradW)
                        : mullerViscosityAcceleration(viscosity, massB, rhoI, restDensity, vi,
                                                      select(near, kernels.laplacian(r), zero));
                a += friction * wallFriction;
              }
              // Walls are not empty space: fluid against a wall is not free surface.
              if constexpr (Options::surfaceTension)
                colourGradient += rib * (volumeB * select(near, kernels.colourGradFactor(r), zero));
            }
          });
    }

    Vec3 ai = (external ? p.gravity + xyz(external[id[i]]) : p.gravity) + sumLanes(a);
    if constexpr (Options::surfaceTension) {
      const Vec3 gradient = sumLanes(colourGradient);
      const float normalLength = length(gradient);
      if (normalLength > p.surfaceThreshold) {
        // Müller et al. 2003 eq. 19: f = -σ ∇²c n/|n|, as an acceleration.
        ai -= gradient * (p.surfaceTension * stdx::reduce(colourLaplacian) / (normalLength * si.w));
      }
    }
    acceleration[i] = makeVec4(ai, 0.0f);
  });
}

}  // namespace sph::fluid::detail

#endif  // !__CUDACC__
