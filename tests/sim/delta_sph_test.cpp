// Continuity density with δ-SPH's diffusion (fluid.density "continuity"): a resting tank holds
// ρ g h with a fraction of the summed density's pressure noise, and runs are the same bytes on
// 1 and 2 threads. Its dam break without corner jets is in corner_jets_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "backends.hpp"
#include "scene/scene_loader.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

Scene shippedScene(const char* name) {
  return scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/" + name);
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
  // Under the sanitizers at twice the spacing, an eighth of the particles and half the steps.
  if (testing::kSanitized) scene.fluid.spacing *= 2.0;
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
