// Flow in and out: an emitter puts its rate × time of fluid in, a layer at a time, on the
// lattice and at its speed; an outlet takes out, and counts, what enters it; the shipped pipe
// carries its flow from the emitter to the outlet without losing a particle through its wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "backends.hpp"
#include "scene/scene_loader.hpp"
#include "sph/core/constants.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

constexpr double kSpacing = 0.01;
constexpr double kSpeed = 0.5;  // m/s
constexpr double kPeriod = kSpacing / kSpeed;

// No gravity, no walls: a disc emitter across x, and a small block far from its stream (a
// scene has fluid to start with).
Scene emitterScene() {
  Scene s;
  s.name = "emitter";
  s.sourcePath = "emitter (test)";
  s.gravity = {0, 0, 0};
  s.fluid.spacing = kSpacing;
  s.fluid.kernel = KernelKind::CubicSpline;
  s.fluid.viscosity = 0.02;
  s.domain.box = {{0, 0, 0}, {0.4, 0.3, 0.3}};
  FluidBlock block;
  block.box = {{0.3, 0.02, 0.02}, {0.34, 0.06, 0.06}};
  s.fluid.blocks.push_back(block);
  EmitterDesc e;
  e.name = "nozzle";
  e.shape = EmitterShape::Disc;
  e.center = {0.05, 0.15, 0.15};
  e.radius = 0.03;
  e.direction = {1, 0, 0};
  e.speed = kSpeed;
  e.start = 0.01;
  s.emitters.push_back(e);
  return s;
}

class Emitters : public ::testing::TestWithParam<Backend> {};

TEST_P(Emitters, PutTheirRateTimesTheTimeOnTheLatticeAtTheirSpeed) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  const Scene scene = emitterScene();
  Simulation sim(scene, testing::on(GetParam()));
  const std::uint64_t initial = sim.fluidCount();
  const double mass = sim.calibration().mass;
  const FlowStats before = sim.emitterStats().at(0);
  EXPECT_EQ(before.particles, 0u);
  const double layer = before.rate * kPeriod;  // particles a layer
  EXPECT_GT(layer, 20.0);                      // π (3 cm)² at 1 cm: 28
  const int periods = testing::kSanitized ? 3 : 6;
  for (int k = 1; k <= periods; ++k) {
    // Just before the k-th period ends: k layers put, the k-th at the emitter's plane.
    const double t = scene.emitters[0].start + k * kPeriod - 1e-6;
    sim.advanceTo(t);
    const FlowStats now = sim.emitterStats().at(0);
    const double expected = before.rate * mass * (t - scene.emitters[0].start);
    EXPECT_NEAR(now.mass, expected, mass) << "after " << k << " periods";
    EXPECT_EQ(now.particles, std::uint64_t(k * std::lround(layer)));
    EXPECT_EQ(sim.fluidCount(), initial + now.particles);
  }
  // The stream: inside the emitter's cylinder, from its plane to as far as it has run, moving
  // at its speed, and no layer put on top of another.
  const ParticleFrame frame = sim.frame(false);
  const double travelled = kSpeed * (sim.time() - scene.emitters[0].start);
  std::size_t inStream = 0;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const float* x = &frame.position[3 * i];
    if (x[0] > 0.25) continue;  // the starting block
    ++inStream;
    EXPECT_GT(x[0], 0.05 - 0.5 * kSpacing);
    EXPECT_LT(x[0], 0.05 + travelled + kSpacing);
    EXPECT_LT(std::hypot(x[1] - 0.15, x[2] - 0.15), 0.03 + 0.5 * kSpacing);
    EXPECT_NEAR(frame.velocity[3 * i], kSpeed, 0.1 * kSpeed);
    EXPECT_LT(frame.density[i], 1.03 * scene.fluid.restDensity) << "particle " << frame.id[i];
  }
  EXPECT_EQ(inStream, sim.emittedCount());
}

TEST_P(Emitters, PutNothingBeforeTheirStartOrAfterTheirEnd) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Scene scene = emitterScene();
  scene.emitters[0].start = 0.02;
  scene.emitters[0].end = 0.02 + 2 * kPeriod - 1e-6;
  Simulation sim(scene, testing::on(GetParam()));
  sim.advanceTo(0.02);
  EXPECT_EQ(sim.emittedCount(), 0u);
  sim.advanceTo(0.02 + 5 * kPeriod);
  const FlowStats f = sim.emitterStats().at(0);
  EXPECT_EQ(f.particles, std::uint64_t(2 * std::lround(f.rate * kPeriod)));
}

// A frame taken right after the step that emitted: the new particles have no neighbour lists
// yet, and the surface flags are not measured from the lists (the sanitizers' build read past
// them). The frame holds every particle, the new ones where the emitter put them.
TEST_P(Emitters, AFrameRightAfterAnEmittingStepHoldsTheNewParticles) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Simulation sim(emitterScene(), testing::on(GetParam()));
  const std::uint64_t initial = sim.fluidCount();
  while (sim.emittedCount() == 0) sim.step();
  const ParticleFrame f = sim.frame(false);
  ASSERT_EQ(f.size(), initial + sim.emittedCount());
  std::size_t atTheNozzle = 0;
  for (std::size_t i = 0; i < f.size(); ++i)
    atTheNozzle += f.position[3 * i] < 0.05 + 2.0 * kSpacing;
  EXPECT_EQ(atTheNozzle, sim.emittedCount());
  EXPECT_EQ(sim.stats().fluidCount, f.size());
}

SPH_ON_EVERY_BACKEND(Emitters);

class Outlets : public ::testing::TestWithParam<Backend> {};

TEST_P(Outlets, RemoveAndCountWhatEntersThem) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Scene scene;
  scene.name = "outlet";
  scene.sourcePath = "outlet (test)";
  scene.gravity = {0, 0, 0};
  scene.fluid.spacing = kSpacing;
  scene.fluid.viscosity = 0.02;
  scene.domain.box = {{0, 0, 0}, {0.4, 0.2, 0.2}};
  FluidBlock block;
  block.box = {{0.02, 0.05, 0.05}, {0.1, 0.13, 0.13}};
  block.velocity = {2.0, 0, 0};
  scene.fluid.blocks.push_back(block);
  scene.outlets.push_back({"sink", {{0.2, 0.0, 0.0}, {0.4, 0.2, 0.2}}});
  scene.outlets.push_back({"elsewhere", {{0.0, 0.15, 0.15}, {0.05, 0.2, 0.2}}});
  Simulation sim(scene, testing::on(GetParam()));
  const std::uint64_t initial = sim.fluidCount();
  sim.advanceTo(0.08);  // the block's front has entered, its back not yet
  const std::vector<FlowStats> midway = sim.outletStats();
  ASSERT_EQ(midway.size(), 2u);
  EXPECT_EQ(midway[0].name, "sink");
  EXPECT_GT(midway[0].particles, 0u);
  EXPECT_LT(midway[0].particles, initial);
  EXPECT_EQ(midway[0].particles + sim.fluidCount(), initial);
  sim.advanceTo(0.25);  // every particle through, and the run goes on empty
  const std::vector<FlowStats> after = sim.outletStats();
  EXPECT_EQ(after[0].particles, initial);
  EXPECT_EQ(after[1].particles, 0u);
  EXPECT_EQ(sim.fluidCount(), 0u);
  EXPECT_EQ(sim.removedCount(), initial);
}

SPH_ON_EVERY_BACKEND(Outlets);

// Every fluid particle of the shipped pipe is inside the pipe (its radius, and a spacing's
// give) or past its open end, on its way into the drain: none went through the wall.
TEST(PipeFlow, CarriesTheFlowFromTheEmitterToTheOutletWithoutLosingAParticle) {
  // Under the sanitizers at 1 cm, an eighth of the particles, for 0.02 s: past the emitter's
  // first layer and the first particles the outlet drains (from 0.01 s).
  const std::string file = std::string(SPH_SOURCE_DIR) + "/scenes/pipe_flow.json";
  const Scene scene =
      testing::kSanitized ? scene::loadScene(file, {"fluid.spacing=0.01"}) : scene::loadScene(file);
  Simulation sim(scene);
  const std::uint64_t initial = sim.fluidCount();
  const double until = testing::kSanitized ? 0.02 : 0.3;
  const double pipeEnd = 0.4;
  const double radius = 0.03 + scene.fluid.spacing;
  while (sim.time() < until) {
    sim.advanceTo(std::min(until, sim.time() + 0.02));
    const ParticleFrame frame = sim.frame(false);
    for (std::size_t i = 0; i < frame.size(); ++i) {
      const float* x = &frame.position[3 * i];
      if (x[0] > pipeEnd) continue;
      ASSERT_LT(std::hypot(x[1] - 0.1, x[2] - 0.05), radius)
          << "particle " << frame.id[i] << " at t = " << sim.time() << " s, x = " << x[0];
      ASSERT_GT(x[0], -0.0025 - scene.fluid.spacing) << "particle " << frame.id[i];
    }
    const std::uint64_t drained = sim.outletStats().at(0).particles;
    ASSERT_EQ(initial + sim.emittedCount(), sim.fluidCount() + drained)
        << "every particle is in the pipe or drained, at t = " << sim.time() << " s";
  }
  EXPECT_GT(sim.emittedCount(), 0u);
  EXPECT_GT(sim.outletStats().at(0).particles, 0u);
}

// Hagen-Poiseuille flow (scenes/poiseuille_pipe.json): a viscous liquid pumped through a pipe
// of radius R at a mean speed U. At steady state, half way along, its velocity is the parabola
// 2U(1 - r²/R²) and its pressure falls by 8 μ U / R² a metre: the viscosity in physical units
// (Müller's model, μ in Pa·s) against no-slip walls (wall_friction 2: the wall takes the
// opposite of the fluid's velocity).
TEST(Poiseuille, PipeFlowHasTheParabolicProfileAndThePressureDrop) {
  const Scene scene =
      scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/poiseuille_pipe.json");
  const double radius = 0.02, mean = scene.emitters.at(0).speed, mu = scene.fluid.viscosity;
  Simulation sim(scene);
  const std::uint64_t initial = sim.fluidCount();
  if (testing::kSanitized) {  // a second a step there: three steps put the first layer in
    sim.advanceTo(0.004);
    EXPECT_GT(sim.emittedCount(), 0u);
    EXPECT_EQ(initial + sim.emittedCount(), sim.fluidCount() + sim.outletStats().at(0).particles);
    return;
  }
  sim.advanceTo(1.5);  // about 1.5 R² / ν: the profile has settled
  sim.takeProbeRows();
  constexpr int kBins = 8;  // rings of equal width, R / 8
  std::vector<double> speedSum(kBins, 0.0);
  std::vector<int> count(kBins, 0);
  for (double t : {1.5, 1.75, 2.0}) {
    sim.advanceTo(t);
    const ParticleFrame frame = sim.frame(false);
    for (std::size_t i = 0; i < frame.size(); ++i) {
      const float* x = &frame.position[3 * i];
      if (x[0] < 0.08 || x[0] > 0.12) continue;  // half way along, two diameters from either end
      const double r = std::hypot(x[1], x[2]);
      const int bin = std::min(kBins - 1, int(r / radius * kBins));
      speedSum[bin] += frame.velocity[3 * i];
      ++count[bin];
    }
  }
  const double peak = 2.0 * mean;
  for (int b = 0; b < kBins; ++b) {
    ASSERT_GT(count[b], 0) << "ring " << b;
    // The parabola's mean over the ring: 2U(1 - (r_in² + r_out²) / (2R²)).
    const double inner = double(b) / kBins, outer = double(b + 1) / kBins;
    const double expected = peak * (1.0 - 0.5 * (inner * inner + outer * outer));
    EXPECT_NEAR(speedSum[b] / count[b], expected, 0.05 * peak)
        << "ring " << b << " (r/R " << inner << " to " << outer << ")";
  }
  // Two point probes on the axis, 8 cm apart, averaged over the last half second.
  const std::vector<std::string>& columns = sim.probeColumns();
  const auto column = [&](const std::string& name) {
    return std::size_t(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  const std::size_t up = column("upstream_pressure_Pa"), down = column("downstream_pressure_Pa");
  ASSERT_LT(up, columns.size());
  ASSERT_LT(down, columns.size());
  double drop = 0.0;
  const std::vector<ProbeRow> rows = sim.takeProbeRows();
  ASSERT_GT(rows.size(), 40u);
  for (const ProbeRow& row : rows) drop += row.values[up] - row.values[down];
  drop /= double(rows.size());
  const double expectedDrop = 8.0 * mu * mean * 0.08 / (radius * radius);
  EXPECT_NEAR(drop, expectedDrop, 0.05 * expectedDrop);
  EXPECT_EQ(initial + sim.emittedCount(), sim.fluidCount() + sim.outletStats().at(0).particles);
}

// Plane Poiseuille flow (Morris, Fox & Zhu 1997, their own test; scenes/poiseuille_channel.json):
// a liquid between two plates W apart, periodic along x and z, set moving from rest by a body
// force F along x. Its velocity is their series solution
//   u(y, t) = F y (W - y) / (2ν) - Σ_n 4 F W² / (ν π³ (2n+1)³) sin((2n+1) π y / W) e^(-(2n+1)² π² ν
//   t / W²)
// at every time: the transient checks the viscosity in physical units, the steady parabola the
// no-slip walls, and both the periodic faces, which the flow crosses all the time.
double planePoiseuille(double y, double t, double width, double force, double nu) {
  double u = force * y * (width - y) / (2.0 * nu);
  for (int n = 0; n < 50; ++n) {
    const double k = 2 * n + 1;
    u -= 4.0 * force * width * width / (nu * std::pow(kPi * k, 3)) * std::sin(k * kPi * y / width) *
         std::exp(-k * k * kPi * kPi * nu * t / (width * width));
  }
  return u;
}

TEST(Poiseuille, PeriodicChannelFollowsMorrisFromRestToTheSteadyParabola) {
  const Scene scene =
      scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/poiseuille_channel.json");
  const double width = 0.02, force = scene.gravity[0];
  const double nu = scene.fluid.viscosity / scene.fluid.restDensity;
  const double peak = force * width * width / (8.0 * nu);  // 1 cm/s on the mid-plane
  Simulation sim(scene);
  const std::uint64_t initial = sim.fluidCount();
  constexpr int kBins = 8;  // layers of equal width across the channel
  // Under the sanitizers, the start of the transient only.
  const std::vector<double> times =
      testing::kSanitized ? std::vector<double>{0.05} : std::vector<double>{0.1, 0.25, 1.0};
  for (double t : times) {
    sim.advanceTo(t);
    const ParticleFrame frame = sim.frame(false);
    std::vector<double> speedSum(kBins, 0.0);
    std::vector<int> count(kBins, 0);
    for (std::size_t i = 0; i < frame.size(); ++i) {
      const int bin = std::clamp(int(frame.position[3 * i + 1] / width * kBins), 0, kBins - 1);
      speedSum[bin] += frame.velocity[3 * i];
      ++count[bin];
    }
    for (int b = 0; b < kBins; ++b) {
      ASSERT_GT(count[b], 0) << "layer " << b;
      // The exact profile averaged over the layer (Simpson's rule: it is smooth there).
      const double lo = width * b / kBins, hi = width * (b + 1) / kBins;
      const double expected = (planePoiseuille(lo, t, width, force, nu) +
                               4.0 * planePoiseuille(0.5 * (lo + hi), t, width, force, nu) +
                               planePoiseuille(hi, t, width, force, nu)) /
                              6.0;
      EXPECT_NEAR(speedSum[b] / count[b], expected, 0.05 * peak)
          << "t " << t << " s, layer " << b << " (y " << lo << " to " << hi << " m)";
    }
  }
  EXPECT_EQ(sim.fluidCount(), initial);
}

}  // namespace
}  // namespace sph
