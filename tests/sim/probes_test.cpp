// The scene's probes in a resting tank: a point probe reads ρ g (H - y), a level gauge the
// water's depth, a point in the air nothing, and the rows come at the probe rate exactly,
// independent of the time step.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "backends.hpp"
#include "scene_builders.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

class Probes : public ::testing::TestWithParam<Backend> {};

std::size_t column(const Simulation& sim, const std::string& name) {
  const std::vector<std::string>& columns = sim.probeColumns();
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return c;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

TEST_P(Probes, InARestingTankReadHydrostaticPressureAndTheWaterLevel) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  const double d = 0.01, width = 0.1, depth = 0.1, g = 9.81;
  Scene scene = testing::restingTank(d, width, depth);
  scene.fluid.kernel = KernelKind::CubicSpline;
  scene.fluid.blocks[0].hydrostatic = true;
  scene.output.probeRate = 200.0;
  ProbeDesc point;
  point.name = "centre";
  point.position = {0.5 * width, 0.5 * depth, 0.5 * width};
  ProbeDesc air;
  air.name = "air";
  air.position = {0.5 * width, 1.15 * depth, 0.5 * width};
  ProbeDesc gauge;
  gauge.name = "gauge";
  gauge.kind = ProbeKind::Level;
  gauge.from = {0.3 * width, 0.0, 0.6 * width};
  gauge.to = {0.3 * width, 2.0 * depth, 0.6 * width};
  scene.probes = {point, air, gauge};
  Simulation sim(scene, testing::on(GetParam()));
  const std::size_t pressure = column(sim, "centre_pressure_Pa");
  const std::size_t airPressure = column(sim, "air_pressure_Pa");
  const std::size_t level = column(sim, "gauge_level_m");
  ASSERT_EQ(sim.probeColumns().size(), 11u);  // 5 for each point, 1 for the gauge

  // Under the sanitizers (a tenth of the speed) the first rows check the sampling's memory; the
  // figures are the Release build's.
  if (testing::kSanitized) {
    sim.advanceTo(0.1);
    const std::vector<ProbeRow> early = sim.takeProbeRows();
    ASSERT_EQ(early.size(), 21u);  // 0, 1/200, ..., 0.1 s
    for (std::size_t k = 0; k < early.size(); ++k) ASSERT_EQ(early[k].time, double(k) / 200.0);
    return;
  }
  // Settled (as the hydrostatic test), then averaged over 0.2 s of rows.
  sim.advanceTo(1.0);
  std::vector<ProbeRow> rows = sim.takeProbeRows();
  ASSERT_EQ(rows.size(), 201u);  // 0, 1/200, ..., 1 s
  for (std::size_t k = 0; k < rows.size(); ++k) ASSERT_EQ(rows[k].time, double(k) / 200.0);
  sim.advanceTo(1.2);
  rows = sim.takeProbeRows();
  ASSERT_EQ(rows.size(), 40u);  // (1, 1.2]
  double meanPressure = 0.0, meanLevel = 0.0;
  for (const ProbeRow& row : rows) {
    meanPressure += row.values[pressure] / double(rows.size());
    meanLevel += row.values[level] / double(rows.size());
    EXPECT_TRUE(std::isnan(row.values[airPressure])) << "at t = " << row.time;
  }
  const double hydrostatic = scene.fluid.restDensity * g * (depth - point.position[1]);
  EXPECT_NEAR(meanPressure, hydrostatic, 0.05 * hydrostatic);
  EXPECT_NEAR(meanLevel, depth, d);
}

SPH_ON_EVERY_BACKEND(Probes);

}  // namespace
}  // namespace sph
