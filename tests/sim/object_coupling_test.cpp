// The step the objects allow and the reach their contacts may have (src/sim/object_coupling.cpp,
// Meteer 2011, §8.3): no object particle may cross more than a quarter of a fluid particle's
// radius in a step, or it could tunnel; under contact coupling the contact spring must also be
// resolved at its stiffest, the influence sphere's centre, where φ = e^β: ω Δt ≤ 1 for
// ω = sqrt(k e^β / m). Contacts are searched in the fluid's grid of cell edge h, so a contact
// reaching past h would be missed and is refused.
#include "sim/object_coupling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/calibration.hpp"
#include "sph/core/contact.hpp"
#include "sph/error.hpp"

namespace sph {
namespace {

constexpr double kBeta = 4.0;

Calibration contactCalibration(double mass, double stiffness) {
  Calibration c;
  c.mass = mass;
  c.contactStiffness = stiffness;
  return c;
}

TEST(ObjectCouplingStep, UnderBoundaryCouplingOnlyTheTravelBoundsIt) {
  sim::ObjectCoupling coupling;
  coupling.params.boundary = true;
  coupling.params.fluidRadius = 0.005f;
  coupling.objectMaxSpeed = 2.0f;
  // A spring this stiff would bound the step at 1e-7 s: the boundary has none.
  const Calibration c = contactCalibration(1e-3, 1e9);
  const double dt = coupling.timeStep(c, kBeta);
  EXPECT_NEAR(dt * 2.0, 0.25 * double(coupling.params.fluidRadius), 1e-12);
  coupling.objectMaxSpeed = 0.0f;
  EXPECT_TRUE(std::isinf(coupling.timeStep(c, kBeta)));  // nothing moves: no bound
}

TEST(ObjectCouplingStep, UnderContactTheSpringOrTheTravelBoundsIt) {
  sim::ObjectCoupling coupling;
  coupling.params.boundary = false;
  coupling.params.fluidRadius = 0.005f;
  const Calibration c = contactCalibration(1e-3, 10.0);
  const double omega = std::sqrt(c.contactStiffness * std::exp(kBeta) / c.mass);  // 740 rad/s
  // Slow: the spring's period bounds it.
  coupling.objectMaxSpeed = 1e-3f;
  EXPECT_NEAR(coupling.timeStep(c, kBeta) * omega, 1.0, 1e-9);
  coupling.objectMaxSpeed = 0.0f;
  EXPECT_NEAR(coupling.timeStep(c, kBeta) * omega, 1.0, 1e-9);
  // Fast: the quarter radius it may cross.
  coupling.objectMaxSpeed = 100.0f;
  const double dt = coupling.timeStep(c, kBeta);
  EXPECT_NEAR(dt * 100.0, 0.25 * double(coupling.params.fluidRadius), 1e-12);
  EXPECT_LT(dt * omega, 1.0);
  // A steeper distance function stiffens the centre, and the step shortens with it.
  coupling.objectMaxSpeed = 0.0f;
  EXPECT_NEAR(coupling.timeStep(c, kBeta + 2.0) * omega, std::exp(-1.0), 1e-9);
}

// Calibrated for the scene, the spring at its stiffest is what the fluid's sound step resolves:
// objects at rest take nothing off the fluid's step.
TEST(ObjectCouplingStep, TheCalibratedSpringAllowsTheFluidsSoundStep) {
  Scene s;
  s.sourcePath = "coupled (test)";
  s.fluid.spacing = 0.01;
  s.fluid.blocks.push_back({{{0, 0, 0}, {0.1, 0.1, 0.1}}, {0, 0, 0}, false, ""});
  ObjectDesc ball;
  ball.shape.kind = ShapeKind::Sphere;
  ball.shape.radius = 0.02;
  s.objects.push_back(ball);
  const Calibration c = sim::calibrate(s);
  sim::ObjectCoupling coupling;
  coupling.params = sim::interactionParameters(s, c);
  const double sound = s.time.cfl * c.supportRadius / c.soundSpeed;
  EXPECT_NEAR(coupling.timeStep(c, s.interaction.distanceExponent) / sound, 1.0, 1e-9);
}

// Two hollow balls, the second at half the spacing: its particles' radii are half as large.
objects::ObjectWorld twoBalls(double spacing) {
  ObjectDesc coarse;
  coarse.name = "coarse";
  coarse.shape.kind = ShapeKind::Sphere;
  coarse.shape.radius = 0.03;
  coarse.spacing = spacing;
  ObjectDesc fine = coarse;
  fine.name = "fine";
  fine.shape.center = {0.1, 0, 0};
  fine.shape.radius = 0.02;
  fine.spacing = 0.5 * spacing;
  objects::WorldSettings settings;
  settings.defaultSpacing = float(spacing);
  settings.sourceName = "scene.json";
  return objects::ObjectWorld({coarse, fine}, settings);
}

std::string refusal(const objects::ObjectWorld& world, float influenceRatio, float fluidRadius,
                    float h) {
  interaction::InteractionParameters p{};
  p.fluidRadius = fluidRadius;
  p.influenceRatio = influenceRatio;
  try {
    sim::ObjectCoupling::checkContactReach(world, p, h, "tank.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ObjectCouplingReach, RefusesAnInfluenceSphereThatReachesPastTheSupport) {
  // Powers of two: the reaches are exact in float.
  const double d = 1.0 / 64.0;
  const float h = float(2.0 * d), fluidRadius = float(0.5 * d);
  const objects::ObjectWorld world = twoBalls(d);
  // The coarse ball's particles (radius d/2) reach d/2 + 3 d/2 = 2 d: h itself, accepted.
  EXPECT_EQ(refusal(world, 3.0f, fluidRadius, h), "");
  EXPECT_EQ(refusal(world, 1.5f, fluidRadius, h), "");
  // A ratio of 3.5 takes it past h; the scene file and the key to change are named.
  const std::string message = refusal(world, 3.5f, fluidRadius, h);
  EXPECT_NE(message.find("tank.json"), std::string::npos) << message;
  EXPECT_NE(message.find("interaction.influence_ratio"), std::string::npos) << message;
  // The fine ball alone (radius d/4) would still be within h at that ratio: the largest
  // particle decides.
  ObjectDesc fine;
  fine.shape.kind = ShapeKind::Sphere;
  fine.shape.radius = 0.02;
  fine.spacing = 0.5 * d;
  objects::WorldSettings settings;
  settings.sourceName = "scene.json";
  const objects::ObjectWorld fineOnly({fine}, settings);
  EXPECT_EQ(refusal(fineOnly, 3.5f, fluidRadius, h), "");
  EXPECT_NE(refusal(fineOnly, 6.5f, fluidRadius, h), "");
}

TEST(ObjectCouplingReach, NoEngineMeansNeitherCoupledNorBoundary) {
  sim::ObjectCoupling coupling;
  EXPECT_FALSE(coupling.coupled());
  EXPECT_FALSE(coupling.asBoundary());
  coupling.params.boundary = true;  // the scene's choice, with nothing to couple
  EXPECT_FALSE(coupling.asBoundary());
}

}  // namespace
}  // namespace sph
