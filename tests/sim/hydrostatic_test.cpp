// A resting tank: after settling, the pressure in each layer carries the weight of the water
// above it (ρ g h with h the depth of water above the layer, by its mass), velocities are
// small and no particle escapes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "backends.hpp"
#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

struct Layer {
  double meanPressure = 0.0;
  double hydrostatic = 0.0;  // weight of the fluid above the layer's centre per unit area
};

Layer layerAt(const ParticleFrame& f, double y, double thickness, double mass, double area) {
  std::size_t above = 0, inLayer = 0;
  double pressureSum = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double yi = f.position[3 * i + 1];
    if (yi > y) ++above;
    if (std::abs(yi - y) < 0.5 * thickness) {
      pressureSum += f.pressure[i];
      ++inLayer;
    }
  }
  Layer layer;
  layer.meanPressure = inLayer ? pressureSum / double(inLayer) : 0.0;
  layer.hydrostatic = double(above) * mass * 9.81 / area;
  return layer;
}

void expectHydrostatic(Backend backend, KernelKind kernel, double tolerance,
                       FluidSolver solver = FluidSolver::Wcsph) {
  const double d = 0.01, width = 0.1, height = 0.1;
  Scene scene = testing::restingTank(d, width, height);
  scene.fluid.kernel = kernel;
  scene.fluid.solver = solver;
  scene.fluid.blocks[0].hydrostatic = true;
  Simulation sim(scene, testing::on(backend));
  // Under the sanitizers (a tenth of the speed) the settling's first steps are a memory check;
  // the figures are the Release build's.
  if (testing::kSanitized) {
    sim.advanceTo(0.05);
    EXPECT_EQ(sim.stats().fluidCount, sim.calibration().fluidParticles);
    return;
  }
  // Settled, then averaged over 0.2 s: what is left of the start's oscillation, a few per cent
  // of ρgh at any one instant, averages out.
  sim.advanceTo(1.0);
  constexpr int kSamples = 5;
  std::vector<double> ratio(7, 0.0), hydrostatic(7, 0.0), pressure(7, 0.0);
  ParticleFrame f;
  for (int k = 0; k < kSamples; ++k) {
    sim.advanceTo(1.0 + 0.05 * k);
    f = sim.frame(false);
    // Layers from two particles above the floor (out of the floor's kernel) to three below
    // the top.
    for (int layer = 2; layer <= 6; ++layer) {
      const Layer l = layerAt(f, (layer + 0.5) * d, d, sim.calibration().mass, width * width);
      ratio[layer] += l.meanPressure / l.hydrostatic / kSamples;
      pressure[layer] += l.meanPressure / kSamples;
      hydrostatic[layer] += l.hydrostatic / kSamples;
    }
  }
  for (int layer = 2; layer <= 6; ++layer)
    EXPECT_NEAR(ratio[layer], 1.0, tolerance)
        << "layer at y = " << (layer + 0.5) * d << ": " << pressure[layer]
        << " Pa, ρgh = " << hydrostatic[layer];

  const FrameStats stats = sim.stats();
  EXPECT_EQ(stats.fluidCount, sim.calibration().fluidParticles);
  EXPECT_EQ(stats.removedCount, 0u);
  // At rest (free fall from the top would be 1.4 m/s): 99 % of the particles below 2 % of that,
  // and the fastest, a jittering surface particle, below 10 %. One particle's speed at one
  // instant is chaotic: a change in the last bit of a kernel value moved it from 0.035 to
  // 0.09 m/s while the 99th percentile stayed at 0.02.
  std::vector<double> speeds;
  for (std::size_t i = 0; i < f.size(); ++i)
    speeds.push_back(std::sqrt(double(f.velocity[3 * i]) * f.velocity[3 * i] +
                               double(f.velocity[3 * i + 1]) * f.velocity[3 * i + 1] +
                               double(f.velocity[3 * i + 2]) * f.velocity[3 * i + 2]));
  std::sort(speeds.begin(), speeds.end());
  EXPECT_LT(speeds[speeds.size() * 99 / 100], 0.03) << "the bulk is not at rest";
  EXPECT_LT(stats.maxSpeed, 0.15) << "a particle is not at rest";

  if (solver == FluidSolver::Dfsph) {
    // The solve met its tolerance on the density the step ends with.
    const SolverStats solve = sim.lastSolve();
    EXPECT_TRUE(solve.converged);
    EXPECT_LE(solve.densityError, scene.fluid.dfsph.densityTolerance);
  }
  if (solver == FluidSolver::Pbf) {
    // The constraints at the default iterations: the mean compression within 1 %, the largest
    // within 5 %.
    const SolverStats solve = sim.lastSolve();
    EXPECT_EQ(solve.densityIterations, scene.fluid.pbf.iterations);
    EXPECT_LE(solve.densityError, 0.01);
    EXPECT_LE(solve.largestDensityError, 0.05);
  }
  for (std::size_t i = 0; i < f.size(); ++i) {
    ASSERT_GT(f.position[3 * i + 1], 0.0f) << "particle " << f.id[i] << " below the floor";
    ASSERT_GT(f.position[3 * i], 0.0f) << "particle " << f.id[i] << " inside a wall";
    ASSERT_LT(f.position[3 * i], width) << "particle " << f.id[i] << " inside a wall";
  }
}

// Kernel and gradient from one function: the lattice gradient is exact within 2 % at h = 2d.
class RestingTank : public ::testing::TestWithParam<Backend> {};

TEST_P(RestingTank, CubicSplineHoldsHydrostaticPressureWithin5Percent) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  expectHydrostatic(GetParam(), KernelKind::CubicSpline, 0.05);
}

// Müller's spiky gradient on poly6 densities reads a linear field 5.3 % low on a lattice at
// h = 2d, so pressure runs that much high to hold the same weight, and more as the lattice
// disorders: measured 4-10 % in the deep layers and 10-17 % three layers below the surface
// over 0.8-1.4 s (the cubic spline stays within 3 %).
TEST_P(RestingTank, MullerHoldsHydrostaticPressureWithin20Percent) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  expectHydrostatic(GetParam(), KernelKind::Muller, 0.20);
}

// The incompressible solver: pressure from the solves, not from an equation of state, the
// divergence solve's share included (it carries what the density solve, stopping at its
// tolerance, left). Measured: 0.1-2.6 % below ρgh by layer; without the divergence solve's share
// 3.2-4.1 % below. The target is 2 %. (With the Müller pair the tank reads 6-11 % above ρgh and
// does not come to rest: its poly6 densities and spiky gradients disagree, and the solve, which
// predicts the one from the other, keeps correcting.)
TEST_P(RestingTank, DfsphCubicSplineHoldsHydrostaticPressureWithin4Percent) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  expectHydrostatic(GetParam(), KernelKind::CubicSpline, 0.04, FluidSolver::Dfsph);
}

// The position solver: pressure from the constraints' multipliers, -ρ0 Σλ/Δt² (core/pbf.hpp),
// not from an equation of state.
TEST_P(RestingTank, PbfCubicSplineHoldsHydrostaticPressureWithin5Percent) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  expectHydrostatic(GetParam(), KernelKind::CubicSpline, 0.05, FluidSolver::Pbf);
}

SPH_ON_EVERY_BACKEND(RestingTank);

}  // namespace
}  // namespace sph
