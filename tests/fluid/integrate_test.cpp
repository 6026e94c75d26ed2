// The integration (integrate.hpp): symplectic Euler, v += Δt a then x += Δt v; the damped box
// reflects a particle at a face; the clamp policy puts it back, stops it moving out, and counts
// it.
#include <gtest/gtest.h>

#include <vector>

#include "fluid_fixture.hpp"

namespace sph::fluid {
namespace {

using namespace testing;

Fluid fluidOf(std::vector<Vec3> x, std::vector<Vec3> v, std::vector<Vec3> a) {
  Lattice lattice{std::move(x), std::move(v)};
  Fluid fluid(lattice, KernelKind::Muller, ViscosityModel::Artificial);
  for (std::size_t i = 0; i < a.size(); ++i)
    fluid.particles.acceleration.data()[i] = makeVec4(a[i]);
  return fluid;
}

TEST(IntegrateStage, IsSymplecticEuler) {
  Fluid fluid = fluidOf({{0.1f, 0.2f, 0.3f}}, {{1.0f, -2.0f, 0.5f}}, {{0.0f, -9.81f, 4.0f}});
  const float dt = 0.01f;
  EXPECT_EQ(integrate(fluid.particles, dt, fluid.domain), 0u);
  const Vec3 v = xyz(fluid.particles.velocity.data()[0]);
  const Vec3 x = xyz(fluid.particles.position.data()[0]);
  EXPECT_FLOAT_EQ(v.x, 1.0f);
  EXPECT_FLOAT_EQ(v.y, -2.0f - 9.81f * dt);
  EXPECT_FLOAT_EQ(v.z, 0.5f + 4.0f * dt);
  EXPECT_FLOAT_EQ(x.x, 0.1f + v.x * dt);  // the new velocity moves it
  EXPECT_FLOAT_EQ(x.y, 0.2f + v.y * dt);
  EXPECT_FLOAT_EQ(x.z, 0.3f + v.z * dt);
}

TEST(IntegrateStage, TheDampedBoxReflectsAtItsFaces) {
  Fluid fluid = fluidOf({{0.0f, 0.995f, 0.0f}}, {{0.0f, 2.0f, 0.0f}}, {{0.0f, 0.0f, 0.0f}});
  fluid.domain.dampedBox = true;
  fluid.domain.damping = 0.5f;
  integrate(fluid.particles, 0.01f, fluid.domain);
  EXPECT_FLOAT_EQ(fluid.particles.position.data()[0].y, 1.0f);
  EXPECT_FLOAT_EQ(fluid.particles.velocity.data()[0].y, -1.0f);
}

TEST(IntegrateStage, TheClampPolicyPutsBackAndCounts) {
  Fluid fluid = fluidOf({{0.0f, 0.995f, 0.0f}, {0.0f, 0.0f, 0.0f}},
                        {{0.0f, 2.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, {{0, 0, 0}, {0, 0, 0}});
  fluid.domain.clampOutside = true;
  EXPECT_EQ(integrate(fluid.particles, 0.01f, fluid.domain), 1u);
  EXPECT_FLOAT_EQ(fluid.particles.position.data()[0].y, 1.0f);
  EXPECT_FLOAT_EQ(fluid.particles.velocity.data()[0].y, 0.0f);
  EXPECT_EQ(fluid.particles.velocity.data()[0].w, 1.0f);  // marked: clamped this step
  EXPECT_FLOAT_EQ(fluid.particles.velocity.data()[1].x, 1.0f);
  EXPECT_EQ(fluid.particles.velocity.data()[1].w, 0.0f);
}

}  // namespace
}  // namespace sph::fluid
