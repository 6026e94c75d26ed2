// The stage templates of src/fluid/, driven directly on the CPU backend, both neighbour walks:
// the density pass against a brute-force kernel sum, the force pass's pair terms cancelling
// across the fluid, and the incompressible solver's density solve undoing a compression
// without creating momentum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "backend/cpu_backend.hpp"
#include "fluid/stages.hpp"
#include "sph/core/kernels.hpp"

namespace sph::fluid {
namespace {

using backend::CpuBackend;

constexpr float kSpacing = 0.01f;
constexpr float kRestDensity = 1000.0f;

// A 10 × 10 × 10 lattice scaled by `scale`, each particle moved by up to `jitter` spacings
// along each axis, with velocities up to `speed` m/s.
struct Lattice {
  std::vector<Vec3> position, velocity;
};

Lattice jitteredLattice(float scale, float jitter, float speed, unsigned seed) {
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

// |Σ_i a_i| / Σ_i |a_i| along each axis (equal masses): 0 where every pair pushes both ways.
struct Imbalance {
  double axis[3] = {0, 0, 0};
  double magnitude = 0.0;  // Σ_i |a_i|
};

Imbalance accelerationImbalance(const FluidParticles<CpuBackend>& particles) {
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

class FluidStages : public ::testing::TestWithParam<NeighborWalk> {};

TEST_P(FluidStages, TheDensityPassSumsTheKernelOverEveryNeighbourWithinTheSupport) {
  const Lattice lattice = jitteredLattice(1.0f, 0.2f, 0.0f, 5);
  for (KernelKind kernel : {KernelKind::CubicSpline, KernelKind::Muller}) {
    Fluid fluid(lattice, kernel, ViscosityModel::Artificial);
    fluid.densityPass(GetParam());
    const std::vector<float> density = fluid.byId(fluid.particles.density);
    const std::vector<std::uint32_t> listed = fluid.byId(fluid.particles.neighborCount);
    const double h = fluid.params.h, h2 = h * h;
    for (std::size_t i = 0; i < lattice.position.size(); ++i) {
      const double expected = kernel == KernelKind::CubicSpline
                                  ? bruteForceDensity(CubicSplineKernels<double>::make(h),
                                                      lattice.position, i, fluid.params.mass)
                                  : bruteForceDensity(MullerKernels<double>::make(h),
                                                      lattice.position, i, fluid.params.mass);
      ASSERT_NEAR(density[i], expected, 2e-5 * expected) << "particle " << i;
      // Every neighbour within h listed, itself not; pairs within rounding of h either way.
      std::uint32_t surely = 0, possibly = 0;
      for (std::size_t j = 0; j < lattice.position.size(); ++j) {
        if (j == i) continue;
        const Vec3 d = lattice.position[i] - lattice.position[j];
        const double r2 = double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
        surely += r2 < h2 * (1.0 - 1e-5);
        possibly += r2 < h2 * (1.0 + 1e-5);
      }
      ASSERT_GE(listed[i], surely) << "particle " << i;
      ASSERT_LE(listed[i], possibly) << "particle " << i;
    }
  }
}

TEST_P(FluidStages, TheForcePassesPairTermsCancelAcrossTheFluid) {
  // Compressed by 3 %, moving at up to 0.5 m/s in every direction: every pair pushes and rubs.
  const Lattice lattice = jitteredLattice(0.97f, 0.2f, 0.5f, 9);
  for (ViscosityModel viscosity : {ViscosityModel::Artificial, ViscosityModel::Muller}) {
    Fluid fluid(lattice, KernelKind::CubicSpline, viscosity);
    fluid.densityPass(GetParam());
    computeForces(fluid.particles, fluid.grid, fluid.walls, fluid.objects, fluid.params,
                  GetParam());
    const Imbalance imbalance = accelerationImbalance(fluid.particles);
    ASSERT_GT(imbalance.magnitude, 1.0);
    for (double share : imbalance.axis) EXPECT_LT(share, 1e-6);  // float rounding
  }
}

TEST_P(FluidStages, TheDensitySolveUndoesACompressionWithoutMakingMomentum) {
  const Lattice lattice = jitteredLattice(0.99f, 0.05f, 0.0f, 13);
  Fluid fluid(lattice, KernelKind::CubicSpline, ViscosityModel::Artificial);
  fluid.params.pressureForces = false;
  fluid.densityPass(GetParam());
  prepareSolver(fluid.particles);
  SolverSettings settings;
  settings.warmStart = false;
  settings.minNeighbours = 20;
  // No iterations: only the first pass, which finds the step's factors.
  CoarsePressure coarse;
  solve(fluid.particles, fluid.grid, fluid.walls, fluid.objects, fluid.params, settings,
        SolverTarget::NoDivergence, 0.0f, GetParam(), coarse);
  settings.tolerance = 1e-4f;
  settings.maxIterations = 200;
  const float dt = 1e-3f;
  const SolverReport report =
      solve(fluid.particles, fluid.grid, fluid.walls, fluid.objects, fluid.params, settings,
            SolverTarget::RestDensity, dt, GetParam(), coarse);
  EXPECT_TRUE(report.converged);
  EXPECT_GT(report.iterations, 1);

  // The solve's accelerations sum to nothing: every pair pushes both ways.
  const Imbalance imbalance = accelerationImbalance(fluid.particles);
  ASSERT_GT(imbalance.magnitude, 1.0);
  for (double share : imbalance.axis) EXPECT_LT(share, 1e-6);

  // Moved by the step the solve predicted over, the block's inner particles (three spacings
  // and more from its faces) are no longer compressed: 3.6 % before on average. The step's
  // density is predicted linearly, and a solve that only pushes does not take back what it
  // overshoots (measured after it: the mean at -0.6 %, the most compressed at +0.6 %).
  struct Errors {
    double mean = 0.0, largest = -1.0;
  };
  const auto innerErrors = [&](const Fluid& f) {
    const std::vector<float> density = f.byId(f.particles.density);
    Errors e;
    int count = 0;
    for (std::size_t i = 0; i < lattice.position.size(); ++i) {
      const int a = int(i / 100), b = int(i / 10 % 10), c = int(i % 10);
      if (std::min({a, b, c}) < 3 || std::max({a, b, c}) > 6) continue;
      const double error = density[i] / kRestDensity - 1.0;
      e.mean += error;
      e.largest = std::max(e.largest, error);
      ++count;
    }
    e.mean /= count;
    return e;
  };
  const Errors before = innerErrors(fluid);
  Lattice moved = lattice;
  const std::vector<Vec4> a = fluid.byId(fluid.particles.acceleration);
  for (std::size_t i = 0; i < moved.position.size(); ++i)
    moved.position[i] = moved.position[i] + xyz(a[i]) * (dt * dt);
  Fluid after(moved, KernelKind::CubicSpline, ViscosityModel::Artificial);
  after.densityPass(GetParam());
  const Errors remaining = innerErrors(after);
  EXPECT_GT(before.mean, 0.03);
  EXPECT_LT(remaining.largest, 0.25 * before.mean) << "from " << before.mean;
  EXPECT_LT(std::abs(remaining.mean), 0.25 * before.mean) << "from " << before.mean;
}

INSTANTIATE_TEST_SUITE_P(BothWalks, FluidStages,
                         ::testing::Values(NeighborWalk::Batched, NeighborWalk::OneAtATime),
                         [](const auto& info) {
                           return info.param == NeighborWalk::Batched ? "batched" : "one_at_a_time";
                         });

}  // namespace
}  // namespace sph::fluid
