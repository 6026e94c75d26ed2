// What the tests of the fluid's stages share: jittered lattices of particles and a fluid on the
// CPU backend, without walls or objects, sized as the engine sizes its arrays.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "backend/cpu_backend.hpp"
#include "fluid/stages.hpp"
#include "sph/core/kernels.hpp"

namespace sph::fluid::testing {

using backend::CpuBackend;

constexpr float kSpacing = 0.01f;
constexpr float kRestDensity = 1000.0f;

// A 10 × 10 × 10 lattice scaled by `scale`, each particle moved by up to `jitter` spacings
// along each axis, with velocities up to `speed` m/s.
struct Lattice {
  std::vector<Vec3> position, velocity;
};

inline Lattice jitteredLattice(float scale, float jitter, float speed, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  Lattice l;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k) {
        const Vec3 x{float(i), float(j), float(k)};
        const Vec3 offset{unit(rng), unit(rng), unit(rng)};
        l.position.push_back((x + offset * jitter) * (kSpacing * scale));
        l.velocity.push_back(Vec3{unit(rng), unit(rng), unit(rng)} * speed);
      }
  return l;
}

// A fluid without walls or objects on the CPU backend, its arrays sized as the engine sizes
// them (src/sim/engine_impl.hpp).
struct Fluid {
  FluidParameters params{};
  DomainParameters domain{};
  FluidParticles<CpuBackend> particles;
  BoundaryParticles<CpuBackend> walls, objects;  // none
  Grid<CpuBackend> grid;

  Fluid(const Lattice& lattice, KernelKind kernel, ViscosityModel viscosity) {
    params.kernel = kernel;
    params.eos = EquationOfState::Linear;
    params.pressureForm = PressureForm::Symmetric;
    params.viscosityModel = viscosity;
    params.clampNegativePressure = false;
    params.pressureForces = true;
    params.h = 2.0f * kSpacing;
    params.restDensity = kRestDensity;
    params.mass = kRestDensity * kSpacing * kSpacing * kSpacing;
    params.soundSpeed = 10.0f;
    params.stiffness = params.soundSpeed * params.soundSpeed;
    params.viscosity = viscosity == ViscosityModel::Artificial ? 0.05f : 0.01f;
    params.surfaceThreshold = 7.0f;
    params.gravity = Vec3{0, 0, 0};
    domain.min = Vec3{-1, -1, -1};
    domain.max = Vec3{1, 1, 1};

    const std::size_t n = lattice.position.size();
    std::vector<Vec4> x(n), v(n), zero(n, Vec4{0, 0, 0, 0});
    std::vector<std::uint32_t> id(n);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = makeVec4(lattice.position[i]);
      v[i] = makeVec4(lattice.velocity[i]);
      id[i] = static_cast<std::uint32_t>(i);
    }
    particles.count = n;
    CpuBackend::upload(particles.position, x.data(), n);
    CpuBackend::upload(particles.velocity, v.data(), n);
    CpuBackend::upload(particles.acceleration, zero.data(), n);
    CpuBackend::upload(particles.id, id.data(), n);
    particles.density.resize(n);
    particles.pressure.resize(n);
    particles.neighborStride = 96;
    for (auto* b : {&particles.scratch4, &particles.pressureState}) b->resize(n);
    for (auto* b :
         {&particles.cell, &particles.order, &particles.scratchId, &particles.neighborCount})
      b->resize(n);
    particles.scratchDensity.resize(n);
    particles.neighbors.resize(n * particles.neighborStride);
    grid.cellSize = params.h;
  }

  void densityPass(NeighborWalk walk) {
    buildGrid(particles, grid, domain);
    computeDensityAndPressure(particles, grid, walls, objects, params, walk);
  }

  // A per-particle array, in the order the particles were made.
  template <class T>
  std::vector<T> byId(const typename CpuBackend::template Buffer<T>& buffer) const {
    std::vector<T> out(particles.count);
    for (std::size_t i = 0; i < particles.count; ++i)
      out[particles.id.data()[i]] = buffer.data()[i];
    return out;
  }
};

template <class Kernels>
double bruteForceDensity(const Kernels& kernels, const std::vector<Vec3>& x, std::size_t i,
                         double mass) {
  double sum = 0.0;
  for (const Vec3& xj : x) {
    const double dx = double(x[i].x) - xj.x, dy = double(x[i].y) - xj.y, dz = double(x[i].z) - xj.z;
    sum += kernels.W(dx * dx + dy * dy + dz * dz);
  }
  return mass * sum;
}

// Particle i's neighbours within h, itself left out, counted pair by pair in double: `surely`
// those inside h by more than rounding, `possibly` those not outside it by more; a walk in
// float must meet a count between the two.
struct BruteNeighbours {
  std::uint32_t surely = 0, possibly = 0;
  double r2 = 0.0;  // Σ r² over those within h
};

inline BruteNeighbours bruteForceNeighbours(const std::vector<Vec3>& x, std::size_t i, double h) {
  const double h2 = h * h;
  BruteNeighbours out;
  for (std::size_t j = 0; j < x.size(); ++j) {
    if (j == i) continue;
    const Vec3 d = x[i] - x[j];
    const double r2 = double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
    out.surely += r2 < h2 * (1.0 - 1e-5);
    out.possibly += r2 < h2 * (1.0 + 1e-5);
    if (r2 < h2) out.r2 += r2;
  }
  return out;
}

// |Σ_i a_i| / Σ_i |a_i| along each axis (equal masses): 0 where every pair pushes both ways.
struct Imbalance {
  double axis[3] = {0, 0, 0};
  double magnitude = 0.0;  // Σ_i |a_i|
};

inline Imbalance accelerationImbalance(const FluidParticles<CpuBackend>& particles) {
  double total[3] = {0, 0, 0};
  Imbalance out;
  for (std::size_t i = 0; i < particles.count; ++i) {
    const Vec4 a = particles.acceleration.data()[i];
    total[0] += a.x;
    total[1] += a.y;
    total[2] += a.z;
    out.magnitude += std::sqrt(double(a.x) * a.x + double(a.y) * a.y + double(a.z) * a.z);
  }
  for (int k = 0; k < 3; ++k) out.axis[k] = std::abs(total[k]) / out.magnitude;
  return out;
}

// Both walks of a pass (neighbor_walk.hpp), by name in the tests' names.
inline std::string walkName(const ::testing::TestParamInfo<NeighborWalk>& info) {
  return info.param == NeighborWalk::Batched ? "batched" : "one_at_a_time";
}
#define SPH_BOTH_WALKS(Suite)                                                                  \
  INSTANTIATE_TEST_SUITE_P(BothWalks, Suite,                                                   \
                           ::testing::Values(NeighborWalk::Batched, NeighborWalk::OneAtATime), \
                           ::sph::fluid::testing::walkName)

}  // namespace sph::fluid::testing
