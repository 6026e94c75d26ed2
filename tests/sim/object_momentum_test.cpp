// Newton's third law across the interaction: with gravity off and no walls, a fluid block that
// hits a free rigid body pushes it, and fluid + body keep their total linear momentum.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "backends.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

Scene blockHitsBody(double rate) {
  Scene s;
  s.name = "block_hits_body";
  s.sourcePath = "block_hits_body (test)";
  s.gravity = {0, 0, 0};
  s.fluid.spacing = 0.01;
  s.fluid.viscosity = 0.1;
  s.domain.box = {{-1, -1, -1}, {1, 1, 1}};
  FluidBlock block;
  block.box = {{-0.1, -0.05, -0.05}, {0.0, 0.05, 0.05}};
  block.velocity = {1.0, 0.1, 0.0};
  s.fluid.blocks.push_back(block);
  ObjectDesc body;
  body.name = "body";
  body.motion = ObjectMotion::Rigid;
  body.shape.kind = ShapeKind::Box;
  body.shape.center = {0.06, 0.01, 0.0};
  body.shape.halfExtents = {0.03, 0.04, 0.03};
  body.density = 800.0;
  s.objects.push_back(body);
  s.objectEngine.rate = rate;
  return s;
}

struct Momentum {
  std::array<double, 3> p{0, 0, 0};
  double scale = 0.0;  // Σ m|v|, what rounding is measured against
};

Momentum totalMomentum(const Simulation& sim) {
  Momentum out;
  const ParticleFrame f = sim.frame(false);
  const double m = sim.calibration().mass;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f.kind[i] != static_cast<std::uint8_t>(ParticleKind::Fluid)) continue;
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      out.p[a] += m * f.velocity[3 * i + a];
      v2 += double(f.velocity[3 * i + a]) * f.velocity[3 * i + a];
    }
    out.scale += m * std::sqrt(v2);
  }
  for (const ObjectStats& o : sim.objectStats()) {
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      out.p[a] += o.mass * o.velocity[a];
      v2 += o.velocity[a] * o.velocity[a];
    }
    out.scale += o.mass * std::sqrt(v2);
  }
  return out;
}

class ObjectMomentum : public ::testing::TestWithParam<Backend> {};

void expectMomentumConserved(const Scene& scene, Backend backend) {
  Simulation sim(scene, testing::on(backend));
  const Momentum before = totalMomentum(sim);
  ASSERT_EQ(sim.objectStats().size(), 1u);
  EXPECT_EQ(sim.objectStats()[0].velocity[0], 0.0);
  std::uint64_t contacts = 0;
  while (sim.time() < 0.15) {
    sim.step();
    contacts = std::max(contacts, sim.stats().contactPairs);
  }
  const Momentum after = totalMomentum(sim);
  // The fluid did push the body.
  EXPECT_GT(contacts, 0u);
  EXPECT_GT(sim.objectStats()[0].velocity[0], 0.05);
  for (int a = 0; a < 3; ++a) {
    // Each pair's two forces are exact negations; what remains is float rounding in the sums
    // and integrations: stated tolerance 1e-5 of the momentum in play.
    EXPECT_NEAR(after.p[a], before.p[a], 1e-5 * before.scale) << "axis " << a;
  }
}

TEST_P(ObjectMomentum, FluidAndRigidBodyConserveLinearMomentum) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  expectMomentumConserved(blockHitsBody(1.0), GetParam());
}

// The body as boundary particles of the incompressible solver's pressure: each object particle
// takes the opposite of what the solves applied to the fluid through it (measured: 1e-8 of the
// momentum in play).
TEST_P(ObjectMomentum, FluidAndRigidBodyConserveLinearMomentumAsBoundaryParticles) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Scene scene = blockHitsBody(1.0);
  scene.fluid.solver = FluidSolver::Dfsph;
  scene.fluid.kernel = KernelKind::CubicSpline;
  scene.interaction.coupling = ObjectCoupling::Boundary;
  expectMomentumConserved(scene, GetParam());
}

// The body as boundary particles of the position solver's density constraints: each object
// particle takes the opposite of what the constraints moved the fluid by through it, iteration
// by iteration, and XSPH's shares are opposite within each pair. Inviscid: the viscous force
// between fluid and body reaches the body in the substep it is found and the fluid in the
// next one's prediction, so a viscous run's momentum leaves one substep's viscous impulse in
// flight (measured at a viscosity of 0.1: 3e-4 of Σm|v| at 9 substeps a frame, 3e-6 at 36).
TEST_P(ObjectMomentum, FluidAndRigidBodyConserveLinearMomentumUnderThePositionSolver) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  Scene scene = blockHitsBody(1.0);
  scene.fluid.solver = FluidSolver::Pbf;
  scene.interaction.coupling = ObjectCoupling::Boundary;
  scene.fluid.viscosity = 0.0;
  expectMomentumConserved(scene, GetParam());
}

// A plate sliding along its own plane through still fluid, gravity off, as boundary particles:
// what moves the fluid is its leading edge's pressure and, along its faces, the fluid's
// viscosity against its particles. Each step the plate feels the opposite of what it gives.
struct SlidingPlate {
  double fluidMomentum = 0.0;  // x, kg m/s
  double plateImpulse = 0.0;   // Σ F_x dt of the fluid on the plate, N s
  double scale = 0.0;          // Σ m|v| of the fluid
};

SlidingPlate slidePlate(Backend backend, ViscosityModel model, double viscosity) {
  Scene s;
  s.name = "sliding_plate";
  s.sourcePath = "sliding_plate (test)";
  s.gravity = {0, 0, 0};
  s.fluid.spacing = 0.01;
  s.fluid.viscosityModel = model;
  s.fluid.viscosity = viscosity;
  s.fluid.solver = FluidSolver::Dfsph;
  s.fluid.kernel = KernelKind::CubicSpline;
  s.interaction.coupling = ObjectCoupling::Boundary;
  s.domain.box = {{-1, -1, -1}, {1, 1, 1}};
  FluidBlock block;
  block.box = {{-0.16, -0.07, -0.07}, {0.16, 0.07, 0.07}};
  s.fluid.blocks.push_back(block);
  ObjectDesc plate;
  plate.name = "plate";
  plate.motion = ObjectMotion::Kinematic;
  plate.shape.kind = ShapeKind::Box;
  plate.shape.center = {-0.04, 0.0, 0.0};
  plate.shape.halfExtents = {0.06, 0.01, 0.05};
  plate.keyframes = {KeyframeDesc{0.0, {0, 0, 0}, {0, 0, 0}},
                     KeyframeDesc{1.0, {0.5, 0, 0}, {0, 0, 0}}};
  s.objects.push_back(plate);
  s.calibration.maxExpectedSpeed = 1.0;
  Simulation sim(s, testing::on(backend));
  SlidingPlate out;
  while (sim.time() < 0.1) {
    const double before = sim.time();
    sim.step();
    out.plateImpulse += sim.objectStats()[0].fluidForce[0] * (sim.time() - before);
  }
  const ParticleFrame f = sim.frame(false);
  const double m = sim.calibration().mass;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f.kind[i] != static_cast<std::uint8_t>(ParticleKind::Fluid)) continue;
    out.fluidMomentum += m * f.velocity[3 * i];
    out.scale += m * std::sqrt(double(f.velocity[3 * i]) * f.velocity[3 * i] +
                               double(f.velocity[3 * i + 1]) * f.velocity[3 * i + 1] +
                               double(f.velocity[3 * i + 2]) * f.velocity[3 * i + 2]);
  }
  return out;
}

TEST_P(ObjectMomentum, ASlidingPlateDragsTheFluidByItsViscosityAndFeelsTheOpposite) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  if (testing::kSanitized) GTEST_SKIP() << "the Release build's figures";
  // Monaghan's α and Müller's μ (Pa s), each against the inviscid run.
  const SlidingPlate inviscid = slidePlate(GetParam(), ViscosityModel::Artificial, 0.0);
  const SlidingPlate artificial = slidePlate(GetParam(), ViscosityModel::Artificial, 0.5);
  const SlidingPlate muller = slidePlate(GetParam(), ViscosityModel::Muller, 3.0);
  std::printf("fluid momentum %.3e (alpha 0.5) %.3e (mu 3 Pa s) %.3e (inviscid) kg m/s\n",
              artificial.fluidMomentum, muller.fluidMomentum, inviscid.fluidMomentum);
  EXPECT_GT(inviscid.fluidMomentum, 0.0);
  EXPECT_GT(artificial.fluidMomentum, 1.5 * inviscid.fluidMomentum);
  EXPECT_GT(muller.fluidMomentum, 1.5 * inviscid.fluidMomentum);
  for (const SlidingPlate& run : {inviscid, artificial, muller})
    EXPECT_NEAR(run.fluidMomentum, -run.plateImpulse, 1e-5 * run.scale);
}

SPH_ON_EVERY_BACKEND(ObjectMomentum);

}  // namespace
}  // namespace sph
