// Bodies in a water tank: a light box floats at the draft Archimedes predicts, a dense ball
// sinks to the floor and rests there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "backends.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

constexpr double kSpacing = 0.01;
constexpr double kBoxHalf[3] = {0.07, 0.04, 0.05};
constexpr double kBallRadius = 0.03;

Scene tankWithBodies() {
  Scene s;
  s.name = "tank_with_bodies";
  s.sourcePath = "tank_with_bodies (test)";
  s.fluid.spacing = kSpacing;
  s.fluid.viscosity = 0.05;
  s.fluid.wallFriction = 1.0;
  s.domain.box = {{-0.05, -0.05, -0.05}, {0.35, 0.45, 0.21}};
  FluidBlock water;
  water.box = {{0, 0, 0}, {0.3, 0.14, 0.16}};
  water.hydrostatic = true;
  s.fluid.blocks.push_back(water);
  s.walls.push_back(WallDesc::tank({{0, 0, 0}, {0.3, 0.3, 0.16}}, 2, false));
  ObjectDesc box;
  box.name = "box";
  box.shape.kind = ShapeKind::Box;
  box.shape.center = {0.1, 0.17, 0.08};
  box.shape.halfExtents = {kBoxHalf[0], kBoxHalf[1], kBoxHalf[2]};
  box.density = 500;
  s.objects.push_back(box);
  ObjectDesc ball;
  ball.name = "ball";
  ball.shape.kind = ShapeKind::Sphere;
  ball.shape.center = {0.24, 0.18, 0.08};
  ball.shape.radius = kBallRadius;
  ball.density = 2700;
  s.objects.push_back(ball);
  s.calibration.maxExpectedSpeed = 1.5;
  return s;
}

// The free surface beside the bodies: the top fluid particle of each lattice column with
// x > 0.2 (clear of the box), averaged, plus half a spacing (the particle's own extent).
double surfaceLevel(const ParticleFrame& f) {
  std::map<std::pair<int, int>, double> top;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f.kind[i] != static_cast<std::uint8_t>(ParticleKind::Fluid)) continue;
    const double x = f.position[3 * i], y = f.position[3 * i + 1], z = f.position[3 * i + 2];
    if (x < 0.2) continue;
    auto key = std::make_pair(int(std::floor(x / kSpacing)), int(std::floor(z / kSpacing)));
    auto it = top.find(key);
    if (it == top.end() || y > it->second) top[key] = y;
  }
  double sum = 0.0;
  for (const auto& column : top) sum += column.second;
  return sum / double(top.size()) + 0.5 * kSpacing;
}

// `draftTolerance`: of Archimedes' draft.
void expectBoxAtArchimedesDraftAndBallOnTheFloor(const Scene& scene, Backend backend,
                                                 double draftTolerance) {
  Simulation sim(scene, testing::on(backend));
  if (testing::kSanitized) {  // a memory check; the figures are the Release build's
    sim.advanceTo(0.05);
    EXPECT_EQ(sim.removedCount(), 0u);
    return;
  }
  sim.advanceTo(1.0);
  // Averaged over 0.25 s of settled bobbing.
  double draft = 0.0, ballHeight = 0.0, ballSpeed = 0.0;
  const int samples = 5;
  for (int k = 0; k < samples; ++k) {
    sim.advanceTo(1.0 + 0.05 * (k + 1));
    const std::vector<ObjectStats> objects = sim.objectStats();
    draft += surfaceLevel(sim.frame(false)) - (objects[0].centreOfMass[1] - kBoxHalf[1]);
    ballHeight += objects[1].centreOfMass[1];
    ballSpeed = std::max(ballSpeed, std::sqrt(objects[1].velocity[0] * objects[1].velocity[0] +
                                              objects[1].velocity[1] * objects[1].velocity[1] +
                                              objects[1].velocity[2] * objects[1].velocity[2]));
  }
  draft /= samples;
  ballHeight /= samples;
  const ObjectStats box = sim.objectStats()[0];
  // Archimedes: ρ0 g A D = M g.
  const double area = 4.0 * kBoxHalf[0] * kBoxHalf[2];
  const double expected = box.mass / (1000.0 * area);
  EXPECT_NEAR(box.mass, 500.0 * 8.0 * kBoxHalf[0] * kBoxHalf[1] * kBoxHalf[2], 1e-6);
  std::printf("draft %.4f m, Archimedes %.4f m (%+.1f %%)\n", draft, expected,
              100.0 * (draft / expected - 1.0));
  EXPECT_NEAR(draft, expected, draftTolerance * expected)
      << "draft " << draft << " m, Archimedes " << expected;
  // The ball lies on the floor (y = 0), its centre a radius up, within a fluid spacing, still.
  EXPECT_NEAR(ballHeight, kBallRadius, kSpacing);
  EXPECT_LT(ballSpeed, 0.02);
  EXPECT_EQ(sim.removedCount(), 0u);
}

class FloatingBodies : public ::testing::TestWithParam<Backend> {};

TEST_P(FloatingBodies, BoxFloatsAtArchimedesDraftAndBallRestsOnTheFloor) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  // Within 5 % with the box 8 fluid spacings tall (measured +2.6 % on the CPU).
  expectBoxAtArchimedesDraftAndBallOnTheFloor(tankWithBodies(), GetParam(), 0.05);
}

// The bodies as boundary particles of the position solver's density constraints: what the
// constraints push the water by, the bodies take back (interaction/boundary_forces.hpp). The
// box floats high, its draft measured 16 % short on the CPU: a sheet of boundary particles
// holds the water a spacing off where a wall holds it half a spacing off (docs/solvers.md,
// "Objects under the position solver"), as under the velocity solver's boundary coupling. Held
// here to 20 % so that it gets no worse; Archimedes within 5 % needs that offset gone.
TEST_P(FloatingBodies, UnderThePositionSolverTheBoxFloatsAndTheBallRests) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Scene scene = tankWithBodies();
  scene.fluid.solver = FluidSolver::Pbf;
  scene.interaction.coupling = ObjectCoupling::Boundary;
  expectBoxAtArchimedesDraftAndBallOnTheFloor(scene, GetParam(), 0.20);
}

SPH_ON_EVERY_BACKEND(FloatingBodies);

}  // namespace
}  // namespace sph
