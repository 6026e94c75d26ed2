// A dam break against a wall that carries a pressure sensor: Buchner's (2002) experiment, a
// column 0.6 m high and 1.2 m wide collapsing along a tank 3.22 m long onto its far wall, as a
// slab periodic across the tank (the 2-D flow the experiment was built to give). The lower
// sensor's pressure, from the surge's arrival through the first second of the impact, against
// the experiment's record.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "backends.hpp"
#include "sph/simulation.hpp"
#include "test_data.hpp"

namespace sph {
namespace {

constexpr double kHeight = 0.6;  // H, m
constexpr double kG = 9.81;
// Buchner's transducers read the mean pressure over their face. Numerical studies of this
// experiment place the lower one 0.09 m tall with its top at the experiment's 0.160 m (Adami,
// Hu & Adams 2012, after Greco et al.); sph samples it at 10 points over that height, half a
// spacing in front of the wall, a point the fluid does not reach or a suction reading 0.
constexpr double kSensorTop = 0.160, kSensorHeight = 0.09;
constexpr int kSensorPoints = 10;

struct Sample {
  double T, P;  // t sqrt(g/H), p/(ρgH)
};

std::vector<Sample> readBuchnerP1() {
  return testing::readTestData<Sample>("buchner_2002_wall_pressure_p1.csv");
}

WallDesc plane(const char* name, Vec3d corner, Vec3d edge1, Vec3d edge2) {
  WallDesc w;
  w.name = name;
  w.kind = WallKind::Plane;
  w.corner = corner;
  w.edge1 = edge1;
  w.edge2 = edge2;
  return w;
}

// `cells` particles across H; the slab is 6 spacings deep (the least a periodic axis takes).
Scene wallImpact(int cells) {
  const double d = kHeight / cells, length = std::round(3.22 / d) * d, depth = 6.0 * d;
  const double top = 3.0 * kHeight, margin = std::max(0.1, 3.0 * d);
  Scene s;
  s.name = "wall_impact";
  s.sourcePath = "wall_impact (test)";
  s.gravity = {0, -kG, 0};
  s.domain.box = {{-margin, -margin, 0}, {length + margin, top + margin, depth}};
  s.domain.periodic = {false, false, true};
  s.fluid.spacing = d;
  s.fluid.kernel = KernelKind::CubicSpline;
  s.fluid.density = DensityModel::Continuity;
  s.fluid.viscosity = 0.02;
  s.fluid.wallFriction = 0.0;
  s.fluid.blocks.push_back({{{0, 0, 0}, {2.0 * kHeight, kHeight, depth}}, {0, 0, 0}, false, ""});
  s.walls.push_back(plane("floor", {-2.0 * d, 0, 0}, {0, 0, depth}, {length + 4.0 * d, 0, 0}));
  s.walls.push_back(plane("back", {0, 0, 0}, {0, top, 0}, {0, 0, depth}));
  s.walls.push_back(plane("far", {length, 0, 0}, {0, 0, depth}, {0, top, 0}));
  for (int k = 0; k < kSensorPoints; ++k) {
    ProbeDesc p;
    p.name = "P1_" + std::to_string(k);
    p.position = {length - 0.5 * d,
                  kSensorTop - kSensorHeight + (k + 0.5) * kSensorHeight / kSensorPoints,
                  0.5 * depth};
    s.probes.push_back(p);
  }
  s.output.probeRate = 1000.0;
  return s;
}

// The sensor's reading at each probe row: the mean of its points' pressures, p/(ρgH).
std::vector<Sample> runToT(Scene scene, Backend backend, double endT) {
  const double toT = std::sqrt(kG / kHeight);
  Simulation sim(scene, testing::on(backend));
  const std::vector<std::string>& columns = sim.probeColumns();
  std::vector<std::size_t> pressure;
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c].find("_pressure_Pa") != std::string::npos) pressure.push_back(c);
  EXPECT_EQ(pressure.size(), std::size_t(kSensorPoints));
  std::vector<Sample> sensor;
  sim.advanceTo(endT / toT);
  for (const ProbeRow& row : sim.takeProbeRows()) {
    double sum = 0.0;
    for (std::size_t c : pressure)
      if (std::isfinite(row.values[c])) sum += std::max(0.0, row.values[c]);
    sensor.push_back({row.time * toT, sum / kSensorPoints / (1000.0 * kG * kHeight)});
  }
  return sensor;
}

// The first time the reading passes `level`.
double firstAbove(const std::vector<Sample>& s, double level) {
  for (const Sample& x : s)
    if (x.P > level) return x.T;
  return 1e9;
}

// The mean over 0.2 in T about `centre`: the impact's peak in a sensor read that way moved by
// a few percent when the run was cut into frames of another length, where over 0.1 in T it
// moved by up to a fifth (the peak of weakly compressible SPH is one acoustic event).
double windowMean(const std::vector<Sample>& s, double centre) {
  double sum = 0.0;
  int n = 0;
  for (const Sample& x : s)
    if (x.T >= centre - 0.1 && x.T < centre + 0.1) {
      sum += x.P;
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

double firstPeak(const std::vector<Sample>& s) {  // over the impact, T 2.4 to 3.4
  double peak = 0.0;
  for (int k = 0; k <= 100; ++k) peak = std::max(peak, windowMean(s, 2.4 + 0.01 * k));
  return peak;
}

double meanOver(const std::vector<Sample>& s, double from, double to) {
  double sum = 0.0;
  int n = 0;
  for (const Sample& x : s)
    if (x.T >= from && x.T <= to) {
      sum += x.P;
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

class WallImpact : public ::testing::TestWithParam<Backend> {};

TEST_P(WallImpact, LowerSensorFollowsBuchner) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  const std::vector<Sample> experiment = readBuchnerP1();
  ASSERT_GE(experiment.size(), 30u) << "test data missing";
  // Under the sanitizers (a tenth of the speed) the collapse's start at H/10, the same walls,
  // periodic slab and sensor, is the memory check; the comparison is the Release build's.
  const std::vector<Sample> sim = testing::kSanitized ? runToT(wallImpact(10), GetParam(), 0.5)
                                                      : runToT(wallImpact(30), GetParam(), 4.6);
  if (testing::kSanitized) return;
  const double arrival = firstAbove(sim, 0.15), expectedArrival = firstAbove(experiment, 0.15);
  const double peak = firstPeak(sim), expectedPeak = firstPeak(experiment);
  const double plateau = meanOver(sim, 3.2, 4.6), expectedPlateau = meanOver(experiment, 3.2, 4.6);
  std::printf(
      "  lower sensor, H/30: past 0.15 at T = %.3f (experiment %.3f); first peak %.3f "
      "(%.3f); T 3.2-4.6 mean %.3f (%.3f)\n",
      arrival, expectedArrival, peak, expectedPeak, plateau, expectedPlateau);
  // Stated tolerances: the arrival within 0.1 in T (25 ms); the impact's peak within 25 %; the
  // pressure that follows within 15 %. Measured here, and over runs cut into frames of 1/20 to
  // 1/77 s: arrival 2.535-2.556 against 2.491; peak 0.564-0.588 against 0.680 (-17 % to
  // -14 %); after it 0.571-0.584 against 0.548 (+4 % to +7 %). At H/20 the peak spread over
  // 0.606-0.822, the mean after it over 0.594-0.611.
  EXPECT_NEAR(arrival, expectedArrival, 0.1);
  EXPECT_NEAR(peak, expectedPeak, 0.25 * expectedPeak);
  EXPECT_NEAR(plateau, expectedPlateau, 0.15 * expectedPlateau);
}

SPH_ON_EVERY_BACKEND(WallImpact);

}  // namespace
}  // namespace sph
