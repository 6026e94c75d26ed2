// The density solve's coarse level (coarse_pressure.hpp) on backend B: the particles it reads
// brought to the host where they are not there already, and its K added to the K records of the
// iteration about to correct the velocities.
#pragma once

#include <vector>

#include "fluid/coarse_pressure.hpp"
#include "fluid/dfsph_passes.hpp"
#include "fluid/particles.hpp"

namespace sph::fluid {

// Adds share × the coarse level's K to each particle's K record. Returns false, adding nothing,
// where the coarse level has nothing to solve.
template <class B>
bool addCoarseCorrection(FluidParticles<B>& fluid, const Grid<B>& grid,
                         const BoundaryParticles<B>& walls, const FluidParameters& params, float dt,
                         float share, CoarsePressure& coarse) {
  const std::size_t n = fluid.count;
  CoarseInput in;
  in.fineGrid = grid.spec;
  in.count = n;
  in.wallCount = walls.count;
  in.particleVolume = params.mass / params.restDensity;
  in.restDensity = params.restDensity;
  in.dt = dt;
  std::vector<Vec4> position, wall;
  std::vector<float> density, error;
  if constexpr (B::kHostMemory) {
    in.position = fluid.position.data();
    in.density = fluid.density.data();
    in.error = fluid.solverSignedError.data();
    in.wall = walls.position.data();
  } else {
    position.resize(n);
    density.resize(n);
    error.resize(n);
    wall.resize(walls.count);
    B::download(fluid.position, position.data(), n);
    B::download(fluid.density, density.data(), n);
    B::download(fluid.solverSignedError, error.data(), n);
    B::download(walls.position, wall.data(), walls.count);
    in.position = position.data();
    in.density = density.data();
    in.error = error.data();
    in.wall = wall.data();
  }
  std::vector<float> k(n);
  if (!coarse.solve(in, k.data())) return false;
  B::upload(fluid.coarseStiffness, k.data(), n);
  const float* add = fluid.coarseStiffness.data();
  float* records = fluid.stiffnessRecords.data();
  B::forEach(
      n, SPH_LAMBDA(std::size_t i) {
        records[kRecordFields * i + SolverRecord::kK] += share * add[i];
      });
  return true;
}

}  // namespace sph::fluid
