// The viewer's probe readings keep each column's latest rows, oldest first, and start over on a
// reset.
#include <gtest/gtest.h>

#include "probe_readings.hpp"

namespace sph::view {
namespace {

ProbeRow row(double t, std::vector<double> values) {
  ProbeRow r;
  r.time = t;
  r.values = std::move(values);
  return r;
}

TEST(ProbeReadings, KeepsTheLastRowsOfEachColumnOldestFirst) {
  ProbeReadings readings(3);
  readings.reset({"deep_pressure_Pa", "gauge_level_m"});
  readings.add({row(0.001, {10, 0.1}), row(0.002, {11, 0.2})});
  readings.add({row(0.003, {12, 0.3}), row(0.004, {13, 0.4})});
  EXPECT_EQ(readings.history(0), (std::vector<float>{11, 12, 13}));
  EXPECT_EQ(readings.history(1), (std::vector<float>{0.2f, 0.3f, 0.4f}));
  EXPECT_EQ(readings.latestTime(), 0.004);
  readings.reset({"push_fx_N"});
  EXPECT_EQ(readings.columns().size(), 1u);
  EXPECT_TRUE(readings.history(0).empty());
}

TEST(ProbeReadings, PlotsPressuresLevelsAndForces) {
  EXPECT_TRUE(ProbeReadings::plotted("deep_pressure_Pa"));
  EXPECT_TRUE(ProbeReadings::plotted("gauge_level_m"));
  EXPECT_TRUE(ProbeReadings::plotted("push_fy_N"));
  EXPECT_FALSE(ProbeReadings::plotted("deep_density_kg_m3"));
  EXPECT_FALSE(ProbeReadings::plotted("deep_vx_m_s"));
}

}  // namespace
}  // namespace sph::view
