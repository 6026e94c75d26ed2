// Deformables under the XPBD model (src/objects/xpbd.*): a pinned chain hangs at the length its
// compliance gives, whatever the engine step, as the spring model's does; constraints break past
// their strain; pinned particles stay; runs repeat bit for bit; stiff constraints neither bound
// the substep nor blow up; bending triples bend as the beam they describe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "hanging_chains.hpp"
#include "object_scenes.hpp"
#include "sph/error.hpp"

namespace sph::objects {
namespace {

using test::settings;

constexpr double kSpacing = test::kChainSpacing;
constexpr double kStiffness = test::kChainStiffness;
constexpr double kG = 9.81;
using test::chain;
using test::hangingChains;
using test::kChainLength;
const Vec3 kGravity = test::kChainGravity;

// The mean over the four chains of (top − bottom) − 9 spacings, after `seconds` at step dt.
double hangingExtension(DeformableModel model, double dt, double seconds = 2.0) {
  ObjectWorld world({hangingChains(model)}, settings(kGravity));
  const int steps = int(std::lround(seconds / dt));
  for (int s = 0; s < steps; ++s) world.step(dt, {});
  const ParticleState& p = world.particles();
  double sum = 0.0;
  for (float xs : {-1.0f, 1.0f})
    for (float zs : {-1.0f, 1.0f}) {
      const std::vector<std::size_t> ids = chain(p, xs, zs);
      EXPECT_EQ(ids.size(), std::size_t(kChainLength));
      for (std::size_t i : ids) EXPECT_LT(std::abs(p.velocity[i].y), 1e-4f) << "not settled";
      sum += p.position[ids.front()].y - p.position[ids.back()].y - (kChainLength - 1) * kSpacing;
    }
  return sum / 4.0;
}

// Link j from the bottom carries j m g: the chain stretches m g / k · N (N − 1) / 2.
double analyticExtension(double mass) {
  return mass * kG / kStiffness * kChainLength * (kChainLength - 1) / 2.0;
}

double particleMass() {
  return ObjectWorld({hangingChains(DeformableModel::Xpbd)}, settings(kGravity))
      .particles()
      .mass[0];
}

TEST(Xpbd, PinnedChainHangsAtTheLengthItsComplianceGives) {
  const double expected = analyticExtension(particleMass());  // 0.90 mm
  const double atMillisecond = hangingExtension(DeformableModel::Xpbd, 1e-3);
  const double atHalf = hangingExtension(DeformableModel::Xpbd, 5e-4);
  EXPECT_NEAR(atMillisecond, expected, 0.05 * expected);
  EXPECT_NEAR(atHalf, expected, 0.05 * expected);
  EXPECT_NEAR(atHalf, atMillisecond, 0.05 * atMillisecond);  // converged in the step
}

TEST(Xpbd, AgreesWithTheSpringModel) {
  const double springs = hangingExtension(DeformableModel::Springs, 1e-3);
  const double xpbd = hangingExtension(DeformableModel::Xpbd, 1e-3);
  EXPECT_NEAR(xpbd, springs, 0.05 * springs);
  EXPECT_NEAR(springs, analyticExtension(particleMass()), 0.01 * springs);
}

TEST(Xpbd, ConstraintBreaksPastItsStrainAndMarksTheCut) {
  test::expectLinksBreakPastTheirStrainAndMarkTheCut(DeformableModel::Xpbd);
}

TEST(Xpbd, CutBoxStartsConstraintsBroken) {
  test::expectCutBoxStartsLinksBrokenAndTheLowerPartFalls(DeformableModel::Xpbd);
}

// A tube pinned at both ends, squeezed by a plate that moves down 8 mm over 0.1 s, with
// bending pairs, a breaking strain, gravity and forces from outside.
std::vector<ObjectDesc> squeezedTube() {
  ObjectDesc vessel = test::tube({0, 0, 0}, 0.01, 0.08, 0.0025);
  vessel.deformable.model = DeformableModel::Xpbd;
  vessel.deformable.stiffness = 100.0;
  vessel.deformable.bendingStiffness = 20.0;
  vessel.deformable.breakingStrain = 0.05;
  vessel.deformable.pinned = {{{-1, -1, -1}, {-0.035, 1, 1}}, {{0.035, -1, -1}, {1, 1, 1}}};
  ObjectDesc clamp =
      test::box({0, 0.0125 + 0.00125, 0}, {0.01, 0.00125, 0.015}, 0.0025, ObjectMotion::Kinematic);
  clamp.name = "clamp";
  clamp.keyframes = {{0.1, {0, -0.008, 0}, {0, 0, 0}}};
  return {vessel, clamp};
}

TEST(Xpbd, PinnedParticlesStayAndRunsRepeatBitForBit) {
  WorldSettings s = settings(kGravity);
  s.contact = {50.0f, 0.005f, 0.0f};
  ObjectWorld a(squeezedTube(), s), b(squeezedTube(), s);
  const std::vector<Vec3> start = a.particles().position;
  std::vector<Vec3> force(start.size(), Vec3{0, 0, 0});
  for (int step = 0; step < 120; ++step) {
    force[step % force.size()] = {1e-4f, 0, 0};
    a.step(1e-3, force);
    b.step(1e-3, force);
  }
  test::expectSameBytes(a.particles(), b.particles());
  const ParticleState& pa = a.particles();

  const ObjectInfo vessel = a.info(0);
  std::size_t pinned = 0;
  float topMiddle = -1.0f;
  for (std::size_t i = vessel.firstParticle; i < vessel.firstParticle + vessel.particleCount; ++i) {
    ASSERT_TRUE(isFinite(pa.position[i]));
    if (pa.pinned[i]) {
      ++pinned;
      EXPECT_EQ(std::memcmp(&pa.position[i], &start[i], sizeof(Vec3)), 0) << "particle " << i;
      EXPECT_EQ(length(pa.velocity[i]), 0.0f);
    } else if (std::abs(pa.position[i].x) < 0.003f) {
      topMiddle = std::max(topMiddle, pa.position[i].y);
    }
  }
  EXPECT_GT(pinned, 0u);
  // The plate (its bottom at 4.5 mm) pushed the tube's top down from 1 cm.
  EXPECT_LT(topMiddle, 0.0045f);
}

// The four chains' particles, from the top down, as they hang at the start.
std::vector<std::vector<std::size_t>> chains(const ParticleState& p) {
  std::vector<std::vector<std::size_t>> all;
  for (float xs : {-1.0f, 1.0f})
    for (float zs : {-1.0f, 1.0f}) all.push_back(chain(p, xs, zs));
  return all;
}

// Kinetic and gravitational (from the start) energy. With the elastic energy, which is never
// negative, it can only fall; the links' stretch is checked on its own.
double motionEnergy(const ParticleState& p, const std::vector<Vec3>& start) {
  double energy = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double m = p.mass[i];
    energy += 0.5 * m * double(dot(p.velocity[i], p.velocity[i]));
    energy += m * kG * (double(p.position[i].y) - double(start[i].y));
  }
  return energy;
}

TEST(Xpbd, StiffChainNeitherBoundsTheSubstepNorBlowsUp) {
  const double stiff = 1e5;  // N/m: ω = √(k / m_red) ≈ 14,000 rad/s on a 1 g particle
  const ObjectWorld springs({hangingChains(DeformableModel::Springs, stiff)}, settings(kGravity));
  EXPECT_LT(springs.stableSubstep(), 1e-3 / 100);  // explicit: over 100 substeps per ms
  ObjectDesc d = hangingChains(DeformableModel::Xpbd, stiff);
  d.velocity = {1, 0, 0};  // whipped sideways: the chains swing up and about
  ObjectWorld world({d}, settings(kGravity));
  EXPECT_TRUE(std::isinf(world.stableSubstep()));

  const ParticleState& p = world.particles();
  const std::vector<Vec3> start = p.position;
  const std::vector<std::vector<std::size_t>> links = chains(p);
  const double initial = motionEnergy(p, start);  // the free particles' 1 m/s
  double largest = initial, longestLink = 0.0, farthest = 0.0;
  for (int s = 0; s < 1000; ++s) {
    world.step(1e-3, {});  // 8 substeps of 0.125 ms: ω h ≈ 1.8
    for (std::size_t i = 0; i < p.size(); ++i) {
      ASSERT_TRUE(isFinite(p.position[i]) && isFinite(p.velocity[i])) << "step " << s;
      farthest = std::max(farthest, test::distance(p.position[i], start[i]));
    }
    largest = std::max(largest, motionEnergy(p, start));
    for (const std::vector<std::size_t>& ids : links)
      for (std::size_t j = 1; j < ids.size(); ++j)
        longestLink =
            std::max(longestLink, test::distance(p.position[ids[j - 1]], p.position[ids[j]]));
  }
  EXPECT_LE(largest, initial * 1.001);      // energy never grows
  EXPECT_LT(longestLink, 1.02 * kSpacing);  // and the stiff links stay within 2 %
  EXPECT_GT(farthest, 0.02);                // the chains did swing
}

// Four horizontal chains of 10 particles along x, the first two of each pinned (clamped): the
// largest drop of a tip after 3 s.
double cantileverTipDrop(double bendingStiffness) {
  ObjectDesc d = test::box({0, 0, 0}, {4.5 * kSpacing, 0.7 * kSpacing, 0.7 * kSpacing}, kSpacing,
                           ObjectMotion::Deformable);
  d.deformable.model = DeformableModel::Xpbd;
  d.deformable.stiffness = kStiffness;
  d.deformable.springReach = 1.2;
  d.deformable.bendingStiffness = bendingStiffness;
  d.deformable.pinned.push_back({{-1, -1, -1}, {-3.4 * kSpacing, 1, 1}});
  ObjectWorld world({d}, settings(kGravity));
  const ParticleState& p = world.particles();
  const std::vector<Vec3> start = p.position;
  for (int s = 0; s < 3000; ++s) world.step(1e-3, {});
  double drop = 0.0;
  for (std::size_t i = 0; i < start.size(); ++i)
    if (start[i].x > 4.4 * kSpacing) drop = std::max(drop, double(start[i].y - p.position[i].y));
  return drop;
}

TEST(Xpbd, BendingTriplesMakeACantileverOfTheBeamTheyDescribe) {
  // A triple's energy ½ k_b (κ/3)², κ = 2 y_j − y_{j−1} − y_{j+1}, is a rotational spring
  // k_b s² / 9 at node j, which carries the moment of the loads beyond it, m g s Σ (i − j):
  // the tip drops Σ_j θ_j (9 − j) s = 9 m g / (2 k_b) Σ_{j=1..8} (9 − j)² (10 − j).
  const double bending = 25.0 * kStiffness;
  double sum = 0.0;
  for (int j = 1; j <= kChainLength - 2; ++j)
    sum += double((kChainLength - 1 - j) * (kChainLength - 1 - j) * (kChainLength - j));
  const double expected = 9.0 * particleMass() * kG / (2.0 * bending) * sum;  // 5.4 mm
  EXPECT_NEAR(cantileverTipDrop(bending), expected, 0.05 * expected);
  EXPECT_GT(cantileverTipDrop(0.0), 0.05);  // without them the 8 cm of free links hang down
}

TEST(Xpbd, BadSubstepsOrBendingIsAnInputErrorNamingTheKey) {
  auto errorOf = [](const ObjectDesc& d) -> std::string {
    try {
      ObjectWorld world({test::box({5, 5, 5}, {0.1, 0.1, 0.1}, 0.01), d}, settings());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  ObjectDesc d = hangingChains(DeformableModel::Xpbd);
  d.deformable.substeps = 0;
  EXPECT_EQ(errorOf(d),
            "scene.json: objects[1].deformable.substeps: expected an integer ≥ 1, got 0");
  d.deformable.substeps = 4;
  d.deformable.bendingStiffness = -1.0;
  EXPECT_NE(errorOf(d).find("objects[1].deformable.bending_stiffness"), std::string::npos);
  d.deformable.bendingStiffness = 0.0;
  EXPECT_EQ(errorOf(d), "");
}

}  // namespace
}  // namespace sph::objects
