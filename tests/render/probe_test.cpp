// The viewer's probe: where it is parked, and the picking that drags it under the cursor.
#include <gtest/gtest.h>

#include "probe.hpp"

namespace sph::view {
namespace {

render::OrbitCamera camera() {
  render::OrbitCamera c;
  c.frame(render::Box3f{{0, 0, 0}, {1, 0.5f, 0.5f}}, 4.0f / 3.0f);
  return c;
}

TEST(Probe, ParkedAboveTheDomainClearOfIt) {
  Scene scene;
  scene.fluid.spacing = 0.01;
  scene.domain.box = {{0, 0, 0}, {1, 0.5, 0.5}};
  const Vec3d centre = addProbe(scene);
  ASSERT_EQ(scene.objects.size(), 1u);
  const ObjectDesc& probe = scene.objects[0];
  EXPECT_EQ(probe.name, kProbeName);
  EXPECT_EQ(probe.motion, ObjectMotion::Kinematic);
  EXPECT_DOUBLE_EQ(probe.shape.radius, 0.03);
  EXPECT_GT(centre[1] - probe.shape.radius, 0.5);  // its lowest point above the domain
  EXPECT_DOUBLE_EQ(centre[0], 0.5);
}

TEST(Probe, TheWindowCentreLooksAtTheTarget) {
  const render::OrbitCamera c = camera();
  const Ray ray = rayThroughPixel(c, 400, 300, 800, 600);
  const render::Vec3f toTarget = render::normalize(render::subtract(c.target, ray.origin));
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(ray.direction[a], toTarget[a], 1e-5f);
}

TEST(Probe, DraggingFollowsTheCursorAtTheProbesDepth) {
  const render::OrbitCamera c = camera();
  // The cursor over the target: the drag point is the target itself.
  const auto centre = dragTarget(c, rayThroughPixel(c, 400, 300, 800, 600), c.target);
  ASSERT_TRUE(centre.has_value());
  for (int a = 0; a < 3; ++a) EXPECT_NEAR((*centre)[a], c.target[a], 1e-4f);
  // To the right on screen: the point moves along the camera's right, at the same depth.
  const auto right = dragTarget(c, rayThroughPixel(c, 600, 300, 800, 600), c.target);
  ASSERT_TRUE(right.has_value());
  const render::Vec3f forward = render::normalize(render::subtract(c.target, c.eye()));
  const render::Vec3f moved = render::subtract(*right, c.target);
  EXPECT_NEAR(render::dot(moved, forward), 0.0f, 1e-4f);
  EXPECT_GT(render::dot(moved, render::cross(forward, {0, 1, 0})), 0.0f);
}

}  // namespace
}  // namespace sph::view
