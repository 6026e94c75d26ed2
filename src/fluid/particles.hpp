// Particle arrays as structures of arrays, grouped by the stage that writes them, in the
// memory of backend B (host for the CPU backend, device for CUDA).
#pragma once

#include <cstddef>
#include <cstdint>

#include "sph/core/grid.hpp"
#include "sph/core/vec.hpp"

namespace sph::fluid {

constexpr std::uint32_t kNeighborOverflow = 0xffffffffu;
// Padding of the arrays the CPU's SIMD passes load a batch at a time: the widest batch (16
// floats, AVX-512).
constexpr std::size_t kBatchPadding = 16;
// Floats in a record of the incompressible solver: 8, so that 8 neighbours load as 8 rows.
constexpr std::uint32_t kRecordFields = 8;
// The position solver's reactions on objects: the fluid particles within 1.5 h of each object
// particle at the predicted positions, listed once a substep. The solve and XSPH move the
// fluid by a small part of h, so the list holds every pair within h at any later positions of
// the substep. A full sphere of 1.5 h at h = 2 spacings holds 113 lattice points, an object's
// surface about half of that.
constexpr float kObjectReach = 1.5f;  // of h
constexpr std::uint32_t kObjectNeighborStride = 96;

// A distributed run's copy of another process's particle (a ghost): its id with this bit set.
// Ghosts are neighbours for the passes and nothing more: the step's measures and counts skip
// them, and the next exchange replaces them.
constexpr std::uint32_t kGhostBit = 0x80000000u;
SPH_HD_INLINE bool isGhost(std::uint32_t id) {
  return (id & kGhostBit) != 0;
}

// Fluid particles, reordered by cell every step so neighbour loops read memory in order.
template <class B>
struct FluidParticles {
  template <class T>
  using Buffer = typename B::template Buffer<T>;
  std::size_t count = 0;
  // state, reordered by buildGrid (n)
  Buffer<Vec4> position;     // xyz, w unused
  Buffer<Vec4> velocity;     // xyz; w = 1 if the clamp policy put the particle back this step
  Buffer<std::uint32_t> id;  // stable particle id
  // computed by computeDensityAndPressure (n); with continuity density (densityIsState), kept
  // across steps, reordered by buildGrid, and advanced by integrateDensity
  bool densityIsState = false;
  Buffer<float> density;
  Buffer<float> pressure;
  Buffer<Vec4> pressureState;  // what the force pass reads of a neighbour: p/ρ², 1/ρ, p, ρ
  // The fluid neighbours (r < h, self excluded) the density pass found, so the force pass
  // visits 30-40 particles instead of the ~200 of 27 cells. Particle i's are
  // neighbors[i·neighborStride ..][0 .. neighborCount[i]); kNeighborOverflow: too many to
  // keep, the force pass searches the cells.
  std::uint32_t neighborStride = 0;
  Buffer<std::uint32_t> neighbors;      // n × neighborStride
  Buffer<std::uint32_t> neighborCount;  // n
  // computed by computeForces (n)
  Buffer<Vec4> acceleration;  // xyz; w = |∇c|, the colour-field gradient (Meteer 2011, eq. 12)
  // set by the embedding application, indexed by particle id; empty when unused
  Buffer<Vec4> externalById;  // xyz: external acceleration, m/s²
  // scratch of buildGrid (n)
  Buffer<std::uint32_t> cell;
  Buffer<std::uint32_t> order;
  Buffer<Vec4> scratch4;
  Buffer<std::uint32_t> scratchId;
  Buffer<float> scratchDensity;
  // The CPU's SIMD density pass: positions as three arrays, padded so that a batch load
  // anywhere in range stays inside (n + kBatchPadding). Empty on the GPU.
  Buffer<float> batchX, batchY, batchZ;
  // What the force or the continuity pass reads of a neighbour, 8 floats a particle (n +
  // kBatchPadding), so that 8 neighbours load as 8 rows and transpose into batches
  // (ForceRecord, ContinuityRecord; neighbor_walk.hpp).
  Buffer<float> batchRecords;
  // The incompressible solver (DFSPH, dfsph_solve.hpp), 8 floats a particle as above (n +
  // kBatchPadding): velocityRecords x, y, z, vx, vy, vz, read while stiffnessRecords are
  // written; stiffnessRecords x, y, z, K, read while velocityRecords are written.
  Buffer<float> velocityRecords, stiffnessRecords;
  Buffer<float> solverFactor;         // β_i (core/dfsph.hpp), per step
  Buffer<Vec4> solverWallGradient;    // xyz: G_w = Σ_b ψ_b ∇W_ib, per step
  Buffer<float> solverTotal;          // Σ K_i applied this solve
  Buffer<std::uint64_t> solverError;  // the last iteration's e_i, fixed point (kErrorScale)
  Buffer<float> solverSignedError;    // the same, signed: < 0 where the fluid would expand
  Buffer<float> coarseStiffness;      // the coarse level's K (coarse_correction.hpp)
  // The position solver (pbf_solve.hpp), per object boundary particle: xyz, Σ over the
  // substep's iterations of what the density constraints moved the fluid by through it, times
  // the fluid's mass (kg m); its reaction is the opposite over Δt². And the fluid particles
  // within 1.5 h of it at the predicted positions, listed once a substep for each iteration's
  // gather (k's from k·kObjectNeighborStride; kNeighborOverflow: too many, search the cells).
  Buffer<Vec4> objectPush;
  Buffer<std::uint32_t> objectNeighbors;
  Buffer<std::uint32_t> objectNeighborCount;
  // ∇W_ij = g_ij (x_i - x_j) of each listed neighbour (n × neighborStride, beside neighbors),
  // kept by the step's first solver pass for the others (neighbor_walk.hpp)
  Buffer<float> pairGradient;
  // Kept across steps, reordered with the particles by buildGrid: x, the density solve's
  // total K; y, the divergence solve's total K times its Δt. Empty unless the solver runs.
  Buffer<Vec4> warmStart;
};

// Boundary particles (Akinci et al. 2012), sorted by cell of their own grid: the static walls,
// once at set-up; or the objects' surface particles where they take part in the fluid's
// density and pressure solve, each time the object engine publishes them (moving: their
// velocity is known).
template <class B>
struct BoundaryParticles {
  template <class T>
  using Buffer = typename B::template Buffer<T>;
  std::size_t count = 0;
  GridSpec grid;                    // covers the particles with a cell to spare
  Buffer<Vec4> position;            // xyz; w = volume ψ_b, m³
  Buffer<Vec4> velocity;            // xyz, m/s; empty for the static walls
  Buffer<std::uint32_t> id;         // stable particle id (walls); the engine's index (objects)
  Buffer<std::uint32_t> cellStart;  // cellCount + 1
  // The CPU's SIMD passes: position and volume as four padded arrays (see FluidParticles).
  // Empty on the GPU.
  Buffer<float> batchX, batchY, batchZ, batchVolume;
};

// The uniform grid over the fluid, rebuilt each step over the particles' bounding box (so an
// empty corner of a large domain costs nothing): particles of cell c are
// [cellStart[c], cellStart[c+1]). The extra last bin holds particles outside the domain.
template <class B>
struct Grid {
  float cellSize = 0.0f;  // h
  // Shared by the processes of a distributed run: the grid spans the bounds of every process's
  // particles (not this one's), and lists each cell's particles in id order (not as the last
  // step left them), so that every process sums a particle's neighbours as one process would.
  bool shared = false;
  Vec3 sharedLo{0, 0, 0}, sharedHi{0, 0, 0};
  GridSpec spec;
  typename B::template Buffer<std::uint32_t> cellStart;  // cellCount + 2
  typename B::SortScratch sortScratch;
};

}  // namespace sph::fluid
