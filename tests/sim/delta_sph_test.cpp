// Continuity density with δ-SPH's diffusion (fluid.density "continuity"): a resting tank holds
// ρ g h with a fraction of the summed density's pressure noise, the dam break has no corner
// jets and loses nothing, and runs are the same bytes on 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "backends.hpp"
#include "io/scene_loader.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

Scene shippedScene(const char* name) {
  return io::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/" + name);
}

struct Reading {
  double mean = 0.0, deviation = 0.0;
};

// Each probe's pressure from `from` to `until`: its mean and standard deviation.
std::vector<Reading> probePressures(const Scene& scene, const std::vector<std::string>& probes,
                                    double from, double until) {
  Simulation sim(scene);
  sim.advanceTo(from);
  sim.takeProbeRows();
  sim.advanceTo(until);
  const std::vector<std::string>& columns = sim.probeColumns();
  const std::vector<ProbeRow> rows = sim.takeProbeRows();
  std::vector<Reading> out;
  for (const std::string& probe : probes) {
    const std::size_t k = std::size_t(
        std::find(columns.begin(), columns.end(), probe + "_pressure_Pa") - columns.begin());
    Reading r;
    for (const ProbeRow& row : rows) r.mean += row.values.at(k);
    r.mean /= double(rows.size());
    for (const ProbeRow& row : rows) r.deviation += std::pow(row.values.at(k) - r.mean, 2);
    r.deviation = std::sqrt(r.deviation / double(rows.size()));
    out.push_back(r);
  }
  return out;
}

// scenes/hydrostatic_tank.json (0.2 m of water, cubic spline) from 1 s to 1.5 s: the probes
// 0.15 and 0.05 m under the surface.
TEST(DeltaSph, RestingTankHoldsRhoGHWithAFractionOfTheNoise) {
  Scene scene = shippedScene("hydrostatic_tank.json");
  const double from = testing::kSanitized ? 0.0 : 1.0;  // once the start's ringing has died
  const double until = testing::kSanitized ? 0.02 : 1.5;
  const Scene summed = scene;
  scene.fluid.density = DensityModel::Continuity;
  const std::vector<std::string> probes{"deep", "shallow"};
  const double depth[] = {0.15, 0.05};
  const std::vector<Reading> c = probePressures(scene, probes, from, until);
  const std::vector<Reading> s = probePressures(summed, probes, from, until);
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const double rhoGH = 1000.0 * 9.81 * depth[k];
    std::printf("  %s: continuity %.1f ± %.2f Pa, summation %.1f ± %.2f Pa, rho g h %.1f Pa\n",
                probes[k].c_str(), c[k].mean, c[k].deviation, s[k].mean, s[k].deviation, rhoGH);
    if (testing::kSanitized) continue;
    EXPECT_NEAR(c[k].mean, rhoGH, 0.02 * rhoGH) << probes[k];
    EXPECT_LT(c[k].deviation, s[k].deviation / 3.0) << probes[k];
  }
}

// scenes/dam_break.json (a 0.2 m column, wall friction 1): until the surge reaches the far
// wall, no particle moves faster than 1.2 √(2gH) (the summed density's corner jets reach twice
// that), nothing is compressed by 3 %, and no particle leaves the tank.
TEST(DeltaSph, DamBreakHasNoCornerJetsAndLosesNothing) {
  Scene scene = shippedScene("dam_break.json");
  scene.fluid.density = DensityModel::Continuity;
  scene.output.format = FrameFormat::None;
  Simulation sim(scene);
  const double limit = 1.2 * std::sqrt(2.0 * 9.81 * 0.2);
  const double farWall = 1.0, spacing = scene.fluid.spacing;
  const double until = testing::kSanitized ? 0.02 : 0.45;  // it arrives at about 0.39 s
  bool arrived = false;
  double fastest = 0.0;
  while (sim.time() < until) {
    sim.advanceTo(std::min(until, sim.time() + 0.01));
    const FrameStats s = sim.stats();
    const ParticleFrame frame = sim.frame(false);
    double front = 0.0;
    for (std::size_t i = 0; i < frame.size(); ++i)
      front = std::max(front, double(frame.position[3 * i]));
    arrived = arrived || front > farWall - 2.0 * spacing;
    if (!arrived) {
      fastest = std::max(fastest, s.maxSpeed);
      EXPECT_LT(s.maxSpeed, limit) << "t = " << sim.time() << " s";
      EXPECT_LT(s.maxDensityError, 0.03) << "t = " << sim.time() << " s";
    }
    ASSERT_EQ(sim.removedCount(), 0u) << "t = " << sim.time() << " s";
  }
  std::printf("  fastest before the surge reached the far wall: %.3f m/s (limit %.3f)\n", fastest,
              limit);
  if (!testing::kSanitized) {
    EXPECT_TRUE(arrived);
  }
}

ParticleFrame runFor(const Scene& scene, int threads, int steps) {
  backend::setThreadCount(threads);
  Simulation sim(scene);
  for (int i = 0; i < steps; ++i) sim.step();
  backend::setThreadCount(0);
  return sim.frame();
}

TEST(DeltaSph, OneAndTwoThreadsGiveTheSameBytes) {
  Scene scene = shippedScene("dam_break.json");
  scene.fluid.density = DensityModel::Continuity;
  const int steps = testing::kSanitized ? 15 : 60;
  const ParticleFrame a = runFor(scene, 1, steps), b = runFor(scene, 2, steps);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.pressure, b.pressure);
}

}  // namespace
}  // namespace sph
