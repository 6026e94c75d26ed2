// Calibration (src/sim/calibration.cpp, Meteer 2011, §8.1): what a scene leaves unset is derived
// from its geometry and material. The mass makes a particle inside the initial lattice read the
// rest density; the sound speed is ten times the largest speed expected (free fall from the
// highest fluid to the lowest floor, and what the fluid starts or enters with), so density
// errors stay near 1 %; the stiffness gives that sound speed, dp/dρ = c0² at rest. The contact
// spring is as stiff as the fluid's sound step resolves at the influence sphere's centre, and
// its dashpot half critical. Values the scene sets are kept and flagged.
#include "sim/calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sph/core/contact.hpp"
#include "sph/core/eos.hpp"
#include "sph/core/kernels.hpp"
#include "sph/core/time_step.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

constexpr double kG = 9.81;

// Water 5 cm deep resting 5 cm above the floor of a tank: it may fall 10 cm.
Scene raisedBlock() {
  Scene s;
  s.name = "raised_block";
  s.sourcePath = "raised_block (test)";
  s.fluid.spacing = 0.01;
  s.domain.box = {{-0.1, -0.1, -0.1}, {0.2, 0.3, 0.2}};
  s.fluid.blocks.push_back({{{0, 0.05, 0}, {0.1, 0.1, 0.1}}, {0, 0, 0}, false, ""});
  s.walls.push_back(WallDesc::tank({{0, 0, 0}, {0.1, 0.15, 0.1}}, 2, false));
  return s;
}

Scene withObject(Scene s) {
  ObjectDesc ball;
  ball.name = "ball";
  ball.shape.kind = ShapeKind::Sphere;
  ball.shape.center = {0.05, 0.12, 0.05};
  ball.shape.radius = 0.02;
  s.objects.push_back(ball);
  return s;
}

const KernelKind kKernels[] = {KernelKind::Muller, KernelKind::CubicSpline, KernelKind::WendlandC2};

TEST(Calibration, TheMassGivesTheLatticeTheRestDensity) {
  for (KernelKind kernel : kKernels) {
    for (double ratio : {1.5, 2.0, 3.0}) {
      Scene s = raisedBlock();
      s.fluid.kernel = kernel;
      s.fluid.supportRatio = ratio;
      s.fluid.restDensity = 998.0;
      const Calibration c = sim::calibrate(s);
      EXPECT_DOUBLE_EQ(c.supportRadius, ratio * s.fluid.spacing);
      EXPECT_NEAR(c.mass * sim::latticeKernelSum(kernel, c.supportRadius, s.fluid.spacing) /
                      s.fluid.restDensity,
                  1.0, 1e-12)
          << "kernel " << int(kernel) << ", h/d " << ratio;
      EXPECT_FALSE(c.massFromScene);
    }
  }
}

// The lattice sum is the kernel's integral sampled on the lattice: Σ W d³ → ∫W = 1 as the
// support spans more spacings.
TEST(Calibration, TheLatticeKernelSumApproachesTheKernelsUnitIntegral) {
  const double d = 0.01;
  for (KernelKind kernel : kKernels) {
    const double coarse = sim::latticeKernelSum(kernel, 2.0 * d, d) * d * d * d;
    const double fine = sim::latticeKernelSum(kernel, 5.0 * d, d) * d * d * d;
    EXPECT_NEAR(fine, 1.0, 0.01) << "kernel " << int(kernel);
    EXPECT_NEAR(coarse, 1.0, 0.15) << "kernel " << int(kernel);
    EXPECT_LT(std::abs(fine - 1.0), std::abs(coarse - 1.0) + 1e-3) << "kernel " << int(kernel);
  }
}

TEST(Calibration, ASupportShorterThanTheSpacingSumsTheParticleAlone) {
  const double d = 0.01, h = 0.8 * d;
  EXPECT_DOUBLE_EQ(sim::latticeKernelSum(KernelKind::Muller, h, d),
                   MullerKernels<double>::make(h).W(0.0));
  EXPECT_DOUBLE_EQ(sim::latticeKernelSum(KernelKind::CubicSpline, h, d),
                   CubicSplineKernels<double>::make(h).W(0.0));
  EXPECT_DOUBLE_EQ(sim::latticeKernelSum(KernelKind::WendlandC2, h, d),
                   WendlandC2Kernels<double>::make(h).W(0.0));
}

// What the mass is for: the engine's own density pass reads the rest density at every particle
// whose neighbourhood lies whole inside the block.
TEST(Calibration, ParticlesInsideTheInitialBlockReadTheRestDensity) {
  for (KernelKind kernel : kKernels) {
    Scene s;
    s.name = "weightless_block";
    s.sourcePath = "weightless_block (test)";
    s.gravity = {0, 0, 0};
    s.fluid.spacing = 0.01;
    s.fluid.kernel = kernel;
    s.calibration.speedOfSound = 10.0;
    s.domain.box = {{-0.1, -0.1, -0.1}, {0.2, 0.2, 0.2}};
    s.fluid.blocks.push_back({{{0, 0, 0}, {0.08, 0.08, 0.08}}, {0, 0, 0}, false, ""});
    Simulation sim(s);
    const ParticleFrame frame = sim.frame(false);
    const double h = sim.calibration().supportRadius;
    std::size_t inside = 0;
    for (std::size_t i = 0; i < frame.size(); ++i) {
      bool whole = true;
      for (int a = 0; a < 3; ++a) {
        const double x = frame.position[3 * i + a];
        whole = whole && x - h > 0.0 && x + h < 0.08;
      }
      if (!whole) continue;
      ++inside;
      EXPECT_NEAR(frame.density[i] / s.fluid.restDensity, 1.0, 1e-4) << "kernel " << int(kernel);
    }
    EXPECT_EQ(inside, 4u * 4u * 4u);  // cells 2 to 5 of 8 along each axis
  }
}

TEST(Calibration, TheSoundSpeedIsTenTimesTheFreeFallFromTheTopToTheFloor) {
  const Calibration c = sim::calibrate(raisedBlock());
  const double fall = std::sqrt(2.0 * kG * 0.1);  // the block's top to the tank's floor
  EXPECT_NEAR(c.maxExpectedSpeed, fall, 1e-12);
  EXPECT_NEAR(c.soundSpeed, 10.0 * fall, 1e-11);
  EXPECT_FALSE(c.maxExpectedSpeedFromScene);
  EXPECT_FALSE(c.soundSpeedFromScene);
  EXPECT_FALSE(c.stiffnessFromScene);
}

TEST(Calibration, AStartingVelocityAddsToTheFallInQuadrature) {
  Scene s = raisedBlock();
  s.fluid.blocks[0].velocity = {0.3, 0.0, -0.4};  // 0.5 m/s
  const Calibration c = sim::calibrate(s);
  EXPECT_NEAR(c.maxExpectedSpeed, std::sqrt(0.25 + 2.0 * kG * 0.1), 1e-12);
  EXPECT_NEAR(c.soundSpeed, 10.0 * c.maxExpectedSpeed, 1e-11);
}

TEST(Calibration, AnEmitterAddsItsSpeedAndFallsFromItsHeight) {
  Scene s = raisedBlock();
  EmitterDesc e;
  e.center = {0.05, 0.3, 0.05};
  e.radius = 0.02;
  e.direction = {0, -1, 0};
  e.speed = 2.0;
  s.emitters.push_back(e);
  const Calibration c = sim::calibrate(s);
  EXPECT_NEAR(c.maxExpectedSpeed, std::sqrt(4.0 + 2.0 * kG * 0.3), 1e-12);
}

// The stiffness gives the sound speed for every equation of state: dp/dρ = c0² at rest.
TEST(Calibration, TheStiffnessMakesDpDrhoTheSoundSpeedSquared) {
  for (EquationOfState eos :
       {EquationOfState::Linear, EquationOfState::Ratio, EquationOfState::Tait}) {
    Scene s = raisedBlock();
    s.fluid.eos = eos;
    const Calibration c = sim::calibrate(s);
    const double rho0 = s.fluid.restDensity, step = 1e-6 * rho0;
    const double dpdrho = (pressureFromDensity(eos, rho0 + step, rho0, c.stiffness, false) -
                           pressureFromDensity(eos, rho0 - step, rho0, c.stiffness, false)) /
                          (2.0 * step);
    EXPECT_NEAR(dpdrho / (c.soundSpeed * c.soundSpeed), 1.0, 1e-6) << "eos " << int(eos);
  }
}

TEST(Calibration, ValuesTheSceneSetsAreKeptAndFlagged) {
  Scene s = raisedBlock();
  s.calibration.mass = 0.25;
  s.calibration.maxExpectedSpeed = 3.0;
  s.calibration.speedOfSound = 12.0;
  s.calibration.stiffness = 5000.0;
  const Calibration c = sim::calibrate(s);
  EXPECT_EQ(c.mass, 0.25);
  EXPECT_EQ(c.maxExpectedSpeed, 3.0);
  EXPECT_EQ(c.soundSpeed, 12.0);
  EXPECT_EQ(c.stiffness, 5000.0);
  EXPECT_TRUE(c.massFromScene);
  EXPECT_TRUE(c.maxExpectedSpeedFromScene);
  EXPECT_TRUE(c.soundSpeedFromScene);
  EXPECT_TRUE(c.stiffnessFromScene);

  // A set expected speed sets the sound speed, and a set sound speed the stiffness.
  Scene speedOnly = raisedBlock();
  speedOnly.calibration.maxExpectedSpeed = 3.0;
  EXPECT_DOUBLE_EQ(sim::calibrate(speedOnly).soundSpeed, 30.0);
  Scene soundOnly = raisedBlock();
  soundOnly.calibration.speedOfSound = 12.0;
  const Calibration fromSound = sim::calibrate(soundOnly);
  EXPECT_EQ(fromSound.soundSpeed, 12.0);
  EXPECT_FALSE(fromSound.stiffnessFromScene);
  EXPECT_DOUBLE_EQ(
      soundSpeedForStiffness(soundOnly.fluid.eos, fromSound.stiffness, soundOnly.fluid.restDensity),
      12.0);
}

// Artificial viscosity α acts like ν = α h c0 / 10 (Monaghan 2005); Müller's μ is dynamic.
TEST(Calibration, TheViscousStepSeesTheKinematicViscosityOfTheModel) {
  Scene s = raisedBlock();
  s.fluid.viscosity = 0.2;
  const Calibration artificial = sim::calibrate(s);
  EXPECT_NEAR(artificial.kinematicViscosity,
              0.2 * artificial.supportRadius * artificial.soundSpeed / 10.0, 1e-15);
  s.fluid.viscosityModel = ViscosityModel::Muller;
  s.fluid.viscosity = 0.001;
  EXPECT_NEAR(sim::calibrate(s).kinematicViscosity, 1e-6, 1e-18);  // water's
}

// The threshold scales as 1/h, so that the same surface is found at any resolution: the 2021
// CUDA SPH tutorial's 7.065 at its h = 2/64.
TEST(Calibration, TheSurfaceThresholdScalesInverselyWithTheSupport) {
  Scene s = raisedBlock();
  s.fluid.spacing = 1.0 / 64.0;
  EXPECT_NEAR(sim::calibrate(s).surfaceThreshold, 7.065, 1e-12);
  s.fluid.spacing = 1.0 / 32.0;
  EXPECT_NEAR(sim::calibrate(s).surfaceThreshold, 7.065 / 2.0, 1e-12);
  s.fluid.surfaceThreshold = 3.0;
  EXPECT_EQ(sim::calibrate(s).surfaceThreshold, 3.0);
}

TEST(Calibration, StepLimitsBoundTheWeaklyCompressibleStepBySound) {
  Scene s = raisedBlock();
  s.fluid.wallFriction = 2.0;
  const Calibration c = sim::calibrate(s);
  const StepLimits l = sim::stepLimits(s, c);
  EXPECT_FALSE(l.followsFlow);
  EXPECT_EQ(l.h, c.supportRadius);
  EXPECT_EQ(l.soundSpeed, c.soundSpeed);
  EXPECT_EQ(l.forceFactor, s.time.forceFactor);
  EXPECT_EQ(l.kinematicViscosity, c.kinematicViscosity);
  EXPECT_EQ(l.wallFriction, 2.0);
  EXPECT_EQ(l.maxDt, s.time.maxDt);
  // At rest the sound still crosses: cfl h / c0 bounds the step even with nothing moving.
  const double sound = s.time.cfl * c.supportRadius / c.soundSpeed;
  EXPECT_LE(longestStep(l, 0.0, 0.0), sound * (1.0 + 1e-12));
  // The first step: the fluid at rest under gravity alone.
  EXPECT_LE(c.initialDt, sound * (1.0 + 1e-12));
  EXPECT_LE(c.initialDt, s.time.forceFactor * std::sqrt(c.supportRadius / kG) * (1.0 + 1e-12));
  EXPECT_DOUBLE_EQ(c.initialDt, longestStep(l, 0.0, kG));
  EXPECT_GT(c.initialDt, 0.0);
}

TEST(Calibration, StepLimitsOfTheIncompressibleSolverFollowTheFlow) {
  Scene s = raisedBlock();
  s.fluid.solver = FluidSolver::Dfsph;
  s.fluid.dfsph.forceFactor = 0.07;
  const Calibration c = sim::calibrate(s);
  const StepLimits l = sim::stepLimits(s, c);
  EXPECT_TRUE(l.followsFlow);
  EXPECT_EQ(l.forceFactor, 0.07);
  // Nothing moving: no sound bound, only the viscous one and the largest step.
  const double viscous =
      viscousTimeStep(l.viscousFactor, l.h, l.kinematicViscosity, l.wallFriction);
  EXPECT_DOUBLE_EQ(longestStep(l, 0.0, 0.0), std::min(viscous, s.time.maxDt));
  EXPECT_GT(longestStep(l, 0.0, 0.0), s.time.cfl * c.supportRadius / c.soundSpeed);
  // A fixed step is the first step.
  s.time.fixedDt = 1.0 / 4096.0;
  EXPECT_EQ(sim::calibrate(s).initialDt, 1.0 / 4096.0);
}

TEST(Calibration, TheContactSpringIsResolvedByTheSoundStepAtItsStiffest) {
  const Scene s = withObject(raisedBlock());
  const Calibration c = sim::calibrate(s);
  const double peak = distanceFunctionPeak(s.interaction.distanceExponent);
  const double sound = s.time.cfl * c.supportRadius / c.soundSpeed;
  // ω = sqrt(k e^β / m) = 1 / dt_CFL.
  EXPECT_NEAR(springTimeStep(c.mass, c.contactStiffness, peak) / sound, 1.0, 1e-12);
  // Half the critical damping 2 sqrt(k m) of that spring at the rim (φ = 1).
  EXPECT_NEAR(c.contactDamping, 0.5 * 2.0 * std::sqrt(c.contactStiffness * c.mass), 1e-12);
  EXPECT_EQ(c.contactShear, 0.0);
  // The pressure acceleration of a fully compressed neighbourhood, c0² / h.
  EXPECT_NEAR(c.maxAcceleration, c.soundSpeed * c.soundSpeed / c.supportRadius, 1e-9);
  EXPECT_FALSE(c.contactStiffnessFromScene);
  EXPECT_FALSE(c.contactDampingFromScene);
  EXPECT_FALSE(c.objectsAsBoundary);
  // A stiffer distance function softens the spring by as much.
  Scene steeper = s;
  steeper.interaction.distanceExponent = 6.0;
  EXPECT_NEAR(sim::calibrate(steeper).contactStiffness * std::exp(2.0), c.contactStiffness,
              1e-9 * c.contactStiffness);
}

TEST(Calibration, TheContactIsCalibratedOnlyWhenThereAreObjects) {
  EXPECT_EQ(sim::calibrate(raisedBlock()).contactStiffness, 0.0);
  EXPECT_EQ(sim::calibrate(raisedBlock()).maxAcceleration, 0.0);
  // An attached engine's objects are met as the scene's own would be.
  EXPECT_DOUBLE_EQ(sim::calibrate(raisedBlock(), true).contactStiffness,
                   sim::calibrate(withObject(raisedBlock())).contactStiffness);
}

TEST(Calibration, ContactValuesTheSceneSetsAreKeptAndFlagged) {
  Scene s = withObject(raisedBlock());
  s.interaction.stiffness = 40.0;
  s.interaction.damping = 0.3;
  s.interaction.shear = 0.1;
  s.interaction.maxAcceleration = 900.0;
  s.interaction.coupling = ObjectCoupling::Boundary;
  const Calibration c = sim::calibrate(s);
  EXPECT_EQ(c.contactStiffness, 40.0);
  EXPECT_EQ(c.contactDamping, 0.3);
  EXPECT_EQ(c.contactShear, 0.1);
  EXPECT_EQ(c.maxAcceleration, 900.0);
  EXPECT_TRUE(c.contactStiffnessFromScene);
  EXPECT_TRUE(c.contactDampingFromScene);
  EXPECT_TRUE(c.contactShearFromScene);
  EXPECT_TRUE(c.maxAccelerationFromScene);
  EXPECT_TRUE(c.objectsAsBoundary);
  // A set spring alone sets the dashpot: still half critical.
  Scene springOnly = withObject(raisedBlock());
  springOnly.interaction.stiffness = 40.0;
  const Calibration d = sim::calibrate(springOnly);
  EXPECT_NEAR(d.contactDamping, std::sqrt(40.0 * d.mass), 1e-12);
}

TEST(Calibration, InteractionParametersCarryTheContactCalibration) {
  Scene s = withObject(raisedBlock());
  s.interaction.influenceRatio = 1.25;
  s.interaction.cutAwareDamping = false;
  const Calibration c = sim::calibrate(s);
  const interaction::InteractionParameters p = sim::interactionParameters(s, c);
  EXPECT_FLOAT_EQ(p.fluidRadius, 0.5f * float(s.fluid.spacing));  // half the fluid spacing
  EXPECT_FLOAT_EQ(p.fluidMass, float(c.mass));
  EXPECT_FLOAT_EQ(p.influenceRatio, 1.25f);
  EXPECT_FLOAT_EQ(p.contact.spring, float(c.contactStiffness));
  EXPECT_FLOAT_EQ(p.contact.damping, float(c.contactDamping));
  EXPECT_FLOAT_EQ(p.contact.shear, float(c.contactShear));
  EXPECT_FLOAT_EQ(p.maxAcceleration, float(c.maxAcceleration));
  EXPECT_FALSE(p.cutAwareDamping);
  EXPECT_FALSE(p.boundary);
  // The distance function: e^β at the influence sphere's centre, 1 at its rim.
  const double beta = s.interaction.distanceExponent;
  EXPECT_FLOAT_EQ(p.distance(0.0f), float(std::exp(beta)));
  EXPECT_FLOAT_EQ(p.distance(1.0f), 1.0f);
  EXPECT_NEAR(p.distance(0.5f), std::exp(0.5 * beta), 1e-3 * std::exp(0.5 * beta));
  // A fluid particle and an object particle of the fluid's radius touch at (1 + ratio) r.
  EXPECT_FLOAT_EQ(interaction::contactReach(p, p.fluidRadius), 2.25f * p.fluidRadius);
  s.interaction.coupling = ObjectCoupling::Boundary;
  EXPECT_TRUE(sim::interactionParameters(s, sim::calibrate(s)).boundary);
}

}  // namespace
}  // namespace sph
