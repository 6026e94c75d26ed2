// The emitters (src/sim/emitters.cpp) and the inflow that feeds their particles to the engine
// (src/sim/inflow.hpp), without a run: a layer enters each time the last has moved one spacing
// on, so by time t an emitter of speed U has put ceil((t - start) U / d) layers, each moved on
// by U for the time since its own moment; the fluid within two spacings downstream is held at
// the emitter's velocity; the new particles take the ids after every particle already made.
// Times and lengths are powers of two, so that the layer counts are exact.
#include "sim/emitters.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "sim/calibration.hpp"
#include "sim/inflow.hpp"
#include "sim/sampling.hpp"
#include "sim/walls.hpp"
#include "sph/core/constants.hpp"

namespace sph {
namespace {

constexpr double kSpacing = 1.0 / 64.0;
constexpr double kSpeed = 0.5;
constexpr double kPeriod = kSpacing / kSpeed;  // 1/32 s
constexpr double kStart = 0.25;
constexpr double kRadius = 3.0 * kSpacing;

EmitterDesc disc() {
  EmitterDesc e;
  e.name = "nozzle";
  e.shape = EmitterShape::Disc;
  e.center = {0.25, 0.5, 0.5};
  e.radius = kRadius;
  e.direction = {0, 0, 2};  // any length
  e.speed = kSpeed;
  e.start = kStart;
  return e;
}

// 4 × 3 spacings, flowing along edge1 × edge2 = +x.
EmitterDesc rectangle() {
  EmitterDesc e;
  e.name = "slot";
  e.shape = EmitterShape::Rectangle;
  e.corner = {0.5, 0.25, 0.25};
  e.edge1 = {0, 4 * kSpacing, 0};
  e.edge2 = {0, 0, 3 * kSpacing};
  e.speed = 2.0 * kSpeed;
  e.start = kStart;
  return e;
}

Scene emitterScene(const std::vector<EmitterDesc>& emitters) {
  Scene s;
  s.name = "emitters";
  s.sourcePath = "emitters (test)";
  s.gravity = {0, 0, 0};
  s.fluid.spacing = kSpacing;
  s.calibration.speedOfSound = 10.0;
  s.domain.box = {{0, 0, 0}, {1, 1, 1}};
  s.fluid.blocks.push_back(
      {{{0.8, 0.8, 0.8}, {0.8 + 4 * kSpacing, 0.8 + 4 * kSpacing, 0.8 + 4 * kSpacing}},
       {0, 0, 0},
       false,
       ""});
  s.emitters = emitters;
  return s;
}

Vec3 at(const Vec3d& origin, const Vec3d& offset) {
  return Vec3{float(origin[0] + offset[0]), float(origin[1] + offset[1]),
              float(origin[2] + offset[2])};
}

TEST(EmitterLayers, ZonesHoldTwoSpacingsDownstreamAtTheEmittersVelocity) {
  const sim::Emitters emitters(emitterScene({disc(), rectangle()}));
  const fluid::InflowZones zones = emitters.zones();
  ASSERT_EQ(zones.count, 2u);
  const double d = kSpacing;

  const fluid::InflowZone& round = zones.zone[0];
  EXPECT_FLOAT_EQ(round.normal.x, 0.0f);
  EXPECT_FLOAT_EQ(round.normal.z, 1.0f);
  EXPECT_FLOAT_EQ(round.speed, float(kSpeed));
  const Vec3d c = disc().center;
  for (double along : {-0.25 * d, 0.0, 0.5 * d, d, 1.5 * d, 1.95 * d})
    for (double side : {0.0, 0.95 * kRadius}) {
      EXPECT_TRUE(fluid::insideInflow(round, at(c, {side, 0, along})))
          << along / d << " spacings on, " << side / d << " off the axis";
      EXPECT_TRUE(fluid::insideInflow(round, at(c, {0, -side, along})));
    }
  for (const Vec3d& outside : {Vec3d{0, 0, 2.05 * d}, Vec3d{0, 0, -d}, Vec3d{0, 0, 3 * d},
                               Vec3d{1.05 * kRadius, 0, d}, Vec3d{0, -1.05 * kRadius, 0.5 * d}})
    EXPECT_FALSE(fluid::insideInflow(round, at(c, outside)))
        << outside[0] << " " << outside[1] << " " << outside[2];

  const fluid::InflowZone& slot = zones.zone[1];
  EXPECT_FLOAT_EQ(slot.normal.x, 1.0f);
  EXPECT_FLOAT_EQ(slot.speed, float(2.0 * kSpeed));
  const EmitterDesc r = rectangle();
  const auto onSlot = [&](double a, double b, double along) {
    return at(r.corner, {along, a * r.edge1[1], b * r.edge2[2]});
  };
  for (double a : {0.05, 0.5, 0.95})
    for (double b : {0.05, 0.5, 0.95})
      for (double along : {0.0, d, 1.95 * d})
        EXPECT_TRUE(fluid::insideInflow(slot, onSlot(a, b, along)));
  EXPECT_FALSE(fluid::insideInflow(slot, onSlot(1.05, 0.5, d)));
  EXPECT_FALSE(fluid::insideInflow(slot, onSlot(0.5, -0.05, d)));
  EXPECT_FALSE(fluid::insideInflow(slot, onSlot(0.5, 0.5, 2.05 * d)));
  EXPECT_FALSE(fluid::insideInflow(slot, onSlot(0.5, 0.5, -d)));
}

// A layer is the opening sampled at the spacing: a rectangle's whole cells, a disc's cells
// within its radius (its area over d², give or take the cells its rim cuts).
TEST(EmitterLayers, ALayerCoversTheOpeningAtTheSpacing) {
  sim::Emitters emitters(emitterScene({disc(), rectangle()}));
  EXPECT_EQ(emitters.layerSize(1), 4u * 3u);
  const double area = kPi * kRadius * kRadius / (kSpacing * kSpacing);
  EXPECT_NEAR(double(emitters.layerSize(0)), area, 2.0 * kPi * kRadius / kSpacing);
  const sim::NewParticles first = emitters.emit(kStart + 0.5 * kPeriod);
  ASSERT_EQ(first.position.size(), emitters.layerSize(0) + emitters.layerSize(1));
  std::set<std::pair<long, long>> cells;
  for (std::size_t i = 0; i < emitters.layerSize(0); ++i) {
    const Vec3& p = first.position[i];
    EXPECT_LT(std::hypot(p.x - 0.25, p.y - 0.5), kRadius);
    // Cell centres of the lattice through the disc's centre, each cell once.
    const double u = (p.x - 0.25) / kSpacing - 0.5, v = (p.y - 0.5) / kSpacing - 0.5;
    EXPECT_NEAR(u, std::round(u), 1e-3);
    EXPECT_NEAR(v, std::round(v), 1e-3);
    cells.insert({std::lround(u), std::lround(v)});
  }
  EXPECT_EQ(cells.size(), emitters.layerSize(0));
}

TEST(EmitterLayers, PutCeilOfThePeriodsSinceTheStartMovedOnAtTheirSpeed) {
  sim::Emitters emitters(emitterScene({disc()}));
  const std::size_t layer = emitters.layerSize(0);
  ASSERT_GT(layer, 0u);
  EXPECT_TRUE(emitters.emit(0.5 * kStart).position.empty());
  EXPECT_TRUE(emitters.emit(kStart).position.empty());  // nothing at the start itself
  EXPECT_EQ(emitters.emittedBy(kStart), 0u);

  // (time since the start in periods, layers due by then)
  const std::pair<double, std::uint64_t> schedule[] = {{0.5, 1},  {1.0, 1}, {2.25, 3},
                                                       {2.75, 3}, {3.0, 3}, {7.5, 8}};
  std::uint64_t before = 0;
  for (const auto& [periods, layers] : schedule) {
    const double t = kStart + periods * kPeriod;
    const sim::NewParticles fresh = emitters.emit(t);
    EXPECT_EQ(fresh.position.size(), (layers - before) * layer) << periods << " periods";
    EXPECT_EQ(emitters.emitted(0), layers * layer);
    EXPECT_EQ(emitters.emittedBy(t), layers * layer);
    EXPECT_NEAR(emitters.particleRate(0) * (t - kStart), double(layers * layer), double(layer));
    // Layer j entered at start + j T and has moved U (t - its moment) along the normal.
    std::vector<std::size_t> perLayer(layers, 0);
    for (std::size_t i = 0; i < fresh.position.size(); ++i) {
      const double travelled = fresh.position[i].z - 0.5;
      const double j = periods - travelled / kSpacing;
      EXPECT_NEAR(j, std::round(j), 1e-3);
      const long k = std::lround(j);
      ASSERT_TRUE(k >= long(before) && k < long(layers)) << "layer " << k;
      ++perLayer[std::size_t(k)];
      EXPECT_EQ(fresh.velocity[i].z, float(kSpeed));
      EXPECT_EQ(fresh.velocity[i].x, 0.0f);
      EXPECT_EQ(fresh.velocity[i].y, 0.0f);
    }
    for (std::uint64_t k = before; k < layers; ++k) EXPECT_EQ(perLayer[k], layer);
    before = layers;
  }
}

TEST(EmitterLayers, PutNothingOnceTheyEnd) {
  EmitterDesc stopping = disc();
  stopping.end = kStart + 2.0 * kPeriod;  // the third layer's moment: it never enters
  EmitterDesc late = rectangle();
  late.start = 1.0;
  sim::Emitters emitters(emitterScene({stopping, late}));
  const std::size_t layer = emitters.layerSize(0);
  EXPECT_EQ(emitters.emit(kStart + 10.0 * kPeriod).position.size(), 2 * layer);
  EXPECT_TRUE(emitters.emit(kStart + 20.0 * kPeriod).position.empty());
  EXPECT_EQ(emitters.emitted(0), 2 * layer);
  EXPECT_EQ(emitters.emitted(1), 0u);  // not started yet
  // The late one runs on: (100 - 1) s at 1 m/s is 6336 of its layers.
  EXPECT_EQ(emitters.emittedBy(100.0), 2 * layer + 6336u * emitters.layerSize(1));
  // Half a period more of running lets the third in.
  EmitterDesc longer = disc();
  longer.end = kStart + 2.5 * kPeriod;
  sim::Emitters three(emitterScene({longer}));
  EXPECT_EQ(three.emit(kStart + 10.0 * kPeriod).position.size(), 3 * layer);
  EXPECT_EQ(three.emittedBy(1e6), 3 * layer);
}

// The ids the engine gives new fluid follow the inflow's nextId, one emit after another.
TEST(Inflow, GivesIdsThatRunOnFromNextId) {
  const Scene scene = emitterScene({disc(), rectangle()});
  const Calibration calibration = sim::calibrate(scene);
  const sim::Walls walls(scene);
  sim::EngineSetup setup = sim::engineSetup(scene, calibration, walls);
  setup.positions = sim::sampleBlock(scene.fluid.blocks[0].box, kSpacing);
  setup.velocities.assign(setup.positions.size(), Vec3{0, 0, 0});
  setup.densities.assign(setup.positions.size(), float(scene.fluid.restDensity));
  const std::unique_ptr<sim::FluidEngine> engine = sim::makeCpuEngine(setup);
  const std::size_t initial = setup.positions.size();
  ASSERT_EQ(initial, 64u);

  sim::Inflow inflow(scene);
  sim::Emitters twin(scene);  // where the same emits put their particles
  const std::uint32_t first = std::uint32_t(initial) + 100;  // as if after walls and objects
  inflow.nextId = first;
  std::vector<Vec3> expected;
  for (double periods : {0.0, 0.5, 2.25}) {
    const double t = kStart + periods * kPeriod;
    inflow.emit(*engine, t);
    const sim::NewParticles fresh = twin.emit(t);
    expected.insert(expected.end(), fresh.position.begin(), fresh.position.end());
    EXPECT_EQ(inflow.nextId, first + expected.size());
    EXPECT_EQ(engine->fluidCount(), initial + expected.size());
  }
  ASSERT_GT(expected.size(), 0u);
  const sim::HostParticles host = engine->download();
  std::size_t seen = 0;
  for (std::size_t i = 0; i < host.id.size(); ++i) {
    const std::uint32_t id = host.id[i];
    if (id < initial) continue;
    ASSERT_GE(id, first);
    ASSERT_LT(id, first + expected.size());
    const Vec3& want = expected[id - first];
    EXPECT_EQ(host.position[i].x, want.x) << "id " << id;
    EXPECT_EQ(host.position[i].y, want.y) << "id " << id;
    EXPECT_EQ(host.position[i].z, want.z) << "id " << id;
    ++seen;
  }
  EXPECT_EQ(seen, expected.size());
  // The zones the step holds are the emitters' own.
  EXPECT_EQ(inflow.zones.count, 2u);
  EXPECT_EQ(inflow.zones.zone[1].speed, twin.zones().zone[1].speed);
}

}  // namespace
}  // namespace sph
