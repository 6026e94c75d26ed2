// The force pass on the CPU, a SIMD batch of neighbours at a time: gathered from the lists the
// density pass made (padded to whole batches), or, for a particle with too many neighbours to
// list, loaded from the contiguous rows of cells. The same sums as forces.hpp (pair_terms.hpp);
// lanes that are not neighbours add nothing.
#pragma once

#if !defined(__CUDACC__)

#include "fluid/batches.hpp"
#include "fluid/pair_terms.hpp"

namespace sph::fluid::detail {

// The record of a listed neighbour: 8 floats, so that 8 neighbours load as 8 rows and
// transpose into batches.
struct ForceRecord {
  enum Field { kX, kY, kZ, kPressureTerm, kVX, kVY, kVZ, kDensity, kFields };
};

template <class Options, class Kernels>
void forcePassBatched(FluidParticles<CpuBackend>& fluid, const Grid<CpuBackend>& grid,
                      const BoundaryParticles<CpuBackend>& boundary,
                      const BoundaryParticles<CpuBackend>& objects, const FluidParameters& params,
                      Kernels kernels) {
  using R = ForceRecord;
  const std::size_t n = fluid.count;
  padArrays(n, 0.0f, {&fluid.batchVX, &fluid.batchVY, &fluid.batchVZ});
  float* vx = fluid.batchVX.data();
  float* vy = fluid.batchVY.data();
  float* vz = fluid.batchVZ.data();
  const Vec4* velocity = fluid.velocity.data();
  // What the pressure term reads of a neighbour (pressureTerm in pair_terms.hpp).
  const float* pressureTermJ = Options::form == PressureForm::Symmetric
                                   ? fluid.batchPOverRho2.data()
                                   : fluid.batchPressure.data();
  const float* density = fluid.batchDensity.data();
  const float* x = fluid.batchX.data();
  const float* y = fluid.batchY.data();
  const float* z = fluid.batchZ.data();
  // The padding's record is far away (never within reach), with no pressure or velocity and a
  // density of 1 to divide by.
  fluid.batchRecords.resize(R::kFields * (n + kBatchPadding));
  float* records = fluid.batchRecords.data();
  CpuBackend::forEach(n + kBatchPadding, [=](std::size_t i) {
    const bool real = i < n;
    const Vec4 v = real ? velocity[i] : Vec4{0.0f, 0.0f, 0.0f, 0.0f};
    if (real) {
      vx[i] = v.x;
      vy[i] = v.y;
      vz[i] = v.z;
    }
    float* r = records + R::kFields * i;
    r[R::kX] = x[i];
    r[R::kY] = y[i];
    r[R::kZ] = z[i];
    r[R::kPressureTerm] = pressureTermJ[i];
    r[R::kVX] = v.x;
    r[R::kVY] = v.y;
    r[R::kVZ] = v.z;
    r[R::kDensity] = density[i];
  });

  const NeighborLists lists = neighborLists(fluid, grid);
  const BoundaryBatches walls = boundaryBatches(boundary);
  const BoundaryBatches objectWalls = boundaryBatches(objects);
  const Vec4* objectVelocity = objects.velocity.data();  // padded with zeros
  const Vec4* state = fluid.pressureState.data();
  Vec4* acceleration = fluid.acceleration.data();
  const std::uint32_t* id = fluid.id.data();
  const Vec4* external = fluid.externalById.size() ? fluid.externalById.data() : nullptr;
  const FluidParameters p = params;
  const float h2 = p.h * p.h;
  const FloatBatch h2Batch(h2), zero(0.0f);

  const ForceConstants<FloatBatch, BatchVec3, Kernels> constants(p, kernels);
  CpuBackend::forEach(n, [=](std::size_t i) {
    const Vec3 xs{x[i], y[i], z[i]};
    const BatchVec3 xi = broadcast(xs);
    const bool seam = nearSeam(p.periodic, xs);
    const ForceTerms<FloatBatch, BatchVec3, Options, Kernels> terms(
        constants, unpackPressureState(state[i]), Vec3{vx[i], vy[i], vz[i]});
    ForceSums<FloatBatch, BatchVec3> sums;
    const auto addFluid = [&](const BatchVec3& xj, const BatchVec3& vj,
                              const FloatBatch& pressureTerm, const FloatBatch& densityJ,
                              const FloatBatch::mask_type& candidates) SPH_BATCH_INLINE_LAMBDA {
      const BatchVec3 rij = separation(p.periodic, seam, xi, xj);
      const FloatBatch r2 = dot(rij, rij);
      const auto near = candidates && r2 < h2Batch;
      if (stdx::none_of(near)) return;
      terms.addFluid(sums, makePair(rij, r2, near, h2), vj, pressureTerm, densityJ);
    };
    forEachNeighborBatch(
        lists, i, xs,
        [&](const std::uint32_t* at) SPH_BATCH_INLINE_LAMBDA {
          FloatBatch c[R::kFields];
          gatherRecords(records, at, c);
          addFluid({c[R::kX], c[R::kY], c[R::kZ]}, {c[R::kVX], c[R::kVY], c[R::kVZ]},
                   c[R::kPressureTerm], c[R::kDensity], FloatBatch::mask_type(true));
        },
        [&](std::uint32_t j, const FloatBatch::mask_type& candidates) {
          addFluid(loadBatch(x, y, z, j), loadBatch(vx, vy, vz, j), loadBatch(pressureTermJ, j),
                   loadBatch(density, j), candidates);
        });
    forEachBoundaryPairBatch(walls, xs, xi, h2,
                             [&](const auto& pair, FloatBatch volume, std::uint32_t) {
                               terms.addWall(sums, pair, volume);
                             });
    forEachBoundaryPairBatch(
        objectWalls, xs, xi, h2, [&](const auto& pair, FloatBatch volume, std::uint32_t k) {
          const BatchVec3 vk{FloatBatch([&](auto lane) { return objectVelocity[k + lane].x; }),
                             FloatBatch([&](auto lane) { return objectVelocity[k + lane].y; }),
                             FloatBatch([&](auto lane) { return objectVelocity[k + lane].z; })};
          terms.addObject(sums, pair, volume, vk);
        });
    const Vec3 extra = external ? xyz(external[id[i]]) : Vec3{0.0f, 0.0f, 0.0f};
    acceleration[i] = makeVec4(terms.total(sums, extra), 0.0f);
  });
}

}  // namespace sph::fluid::detail

#endif  // !__CUDACC__
