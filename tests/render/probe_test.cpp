// The viewer's probe: where it is parked, and the picking that grabs it, or any kinematic
// object, under the cursor and drags it.
#include <gtest/gtest.h>

#include "probe.hpp"

#include <cstdint>
#include <vector>

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

// Two objects on the line of sight and one beside it: the click takes the nearest one it may
// move, within reach of the ray.
TEST(Probe, AClickGrabsTheNearestKinematicObjectUnderTheCursor) {
  const render::OrbitCamera c = camera();
  const Ray ray = rayThroughPixel(c, 400, 300, 800, 600);
  const auto onRay = [&](float t, float aside) {
    const render::Vec3f side = render::normalize(render::cross(ray.direction, {0, 1, 0}));
    return render::add(render::add(ray.origin, render::scale(ray.direction, t)),
                       render::scale(side, aside));
  };
  std::vector<float> position;
  std::vector<std::int32_t> object;
  const auto place = [&](render::Vec3f p, std::int32_t o) {
    for (int a = 0; a < 3; ++a) position.push_back(p[a]);
    object.push_back(o);
  };
  place(onRay(0.5f, 0.0f), -1);   // fluid, in front of everything
  place(onRay(0.8f, 0.002f), 0);  // a rigid body (not grabbable), in front
  place(onRay(1.0f, 0.004f), 1);  // a clamp, behind it
  place(onRay(1.2f, 0.0f), 2);    // another, further
  place(onRay(0.6f, 0.05f), 2);   // ... whose other particle is off the ray
  place(onRay(-0.5f, 0.0f), 1);   // behind the eye
  const std::vector<bool> kinematic = {false, true, true};
  const auto pick = pickObject(ray, position, object, kinematic, 0.01f);
  ASSERT_TRUE(pick.has_value());
  EXPECT_EQ(pick->object, 1u);
  EXPECT_NEAR(pick->distance, 1.0f, 1e-4f);
  // A tighter reach misses the clamp (4 mm off the ray) and takes the one on it.
  const auto tight = pickObject(ray, position, object, kinematic, 0.003f);
  ASSERT_TRUE(tight.has_value());
  EXPECT_EQ(tight->object, 2u);
  // Nothing that may move under the cursor: nothing grabbed.
  EXPECT_FALSE(pickObject(ray, position, object, {true, false, false}, 0.001f).has_value());
  EXPECT_FALSE(pickObject(ray, position, object, {}, 1.0f).has_value());
}

}  // namespace
}  // namespace sph::view
