// The orbit camera frames what it is given: every corner or point lands inside the picture, and
// fills a fair part of it.
#include "camera.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "wireframe.hpp"

namespace sph::render {
namespace {

// Normalised device coordinates of p (x and y in [-1, 1] when in sight), and its depth in [-1, 1].
std::array<float, 3> project(const OrbitCamera& camera, float aspect, const Vec3f& p) {
  const auto clip = transformPoint(multiply(camera.projection(aspect), camera.view()), p);
  return {clip[0] / clip[3], clip[1] / clip[3], clip[2] / clip[3]};
}

std::vector<Vec3f> corners(const Box3f& box) {
  std::vector<Vec3f> out;
  for (int c = 0; c < 8; ++c)
    out.push_back({c & 1 ? box.max[0] : box.min[0], c & 2 ? box.max[1] : box.min[1],
                   c & 4 ? box.max[2] : box.min[2]});
  return out;
}

TEST(Camera, TargetIsInTheMiddleOfThePicture) {
  OrbitCamera camera;
  camera.target = {1, 2, 3};
  camera.distance = 5;
  camera.yaw = 0.3f;
  camera.pitch = 0.4f;
  const auto ndc = project(camera, 1.5f, camera.target);
  EXPECT_NEAR(ndc[0], 0.0f, 1e-5f);
  EXPECT_NEAR(ndc[1], 0.0f, 1e-5f);
  const auto eye = camera.eye();
  const float d = std::hypot(eye[0] - 1, eye[1] - 2, eye[2] - 3);
  EXPECT_NEAR(d, 5.0f, 1e-4f);
  EXPECT_GT(eye[1], 2.0f);  // positive pitch looks down from above
}

TEST(Camera, FramedBoxCornersAreInsideTheViewport) {
  for (const float aspect : {16.0f / 9.0f, 1.0f, 0.5f}) {
    const Box3f box{{-0.01f, -0.02f, -0.02f}, {0.05f, 0.02f, 0.02f}};
    OrbitCamera camera;
    camera.frame(box, aspect);
    float widest = 0.0f;
    for (const Vec3f& corner : corners(box)) {
      const auto ndc = project(camera, aspect, corner);
      EXPECT_LT(std::abs(ndc[0]), 1.0f) << "aspect " << aspect;
      EXPECT_LT(std::abs(ndc[1]), 1.0f) << "aspect " << aspect;
      EXPECT_LT(std::abs(ndc[2]), 1.0f) << "in front of the near plane, before the far one";
      widest = std::max({widest, std::abs(ndc[0]), std::abs(ndc[1])});
    }
    EXPECT_GT(widest, 0.75f) << "the box should fill the picture, aspect " << aspect;
  }
}

TEST(Camera, FramedFromBelowTheBoxIsStillInTheViewport) {
  const Box3f box{{-0.01f, -0.02f, -0.02f}, {0.05f, 0.02f, 0.02f}};
  OrbitCamera camera;
  camera.frame(box, 16.0f / 9.0f, -20.0f, -30.0f);
  EXPECT_LT(camera.eye()[1], camera.target[1]);  // looking up at it
  for (const Vec3f& corner : corners(box)) {
    const auto ndc = project(camera, 16.0f / 9.0f, corner);
    EXPECT_LT(std::abs(ndc[0]), 1.0f);
    EXPECT_LT(std::abs(ndc[1]), 1.0f);
  }
}

TEST(Camera, FramedPointsAreCentredAndInside) {
  std::vector<Vec3f> points;
  for (int i = 0; i < 50; ++i) {
    const float a = 0.3f * static_cast<float>(i);
    points.push_back({0.001f * static_cast<float>(i), 0.006f * std::cos(a), 0.006f * std::sin(a)});
  }
  OrbitCamera camera;
  camera.frame(points, 16.0f / 9.0f);
  float low[2] = {1, 1}, high[2] = {-1, -1};
  for (const Vec3f& p : points) {
    const auto ndc = project(camera, 16.0f / 9.0f, p);
    for (int k = 0; k < 2; ++k) {
      low[k] = std::min(low[k], ndc[k]);
      high[k] = std::max(high[k], ndc[k]);
    }
  }
  for (int k = 0; k < 2; ++k) {
    EXPECT_GT(low[k], -1.0f);
    EXPECT_LT(high[k], 1.0f);
    EXPECT_NEAR(low[k] + high[k], 0.0f, 0.05f) << "centred along axis " << k;
  }
}

TEST(Wireframe, BoxHasTwelveEdgesAndGridItsCells) {
  const Box3f box{{0, 0, 0}, {1, 2, 3}};
  EXPECT_EQ(boxEdges(box).size(), 12u * 2 * 3);
  // Cells of 0.5: 2 × 4 × 6. Each back face has (cells + 1) lines along each of its two axes.
  const std::vector<float> grid = gridOnBackFaces(box, 0.5f, {5, 5, 5});
  const std::size_t lines = (4 + 1) + (6 + 1) + (6 + 1) + (2 + 1) + (2 + 1) + (4 + 1);
  EXPECT_EQ(grid.size(), lines * 6);
  // The eye is beyond every max face: the lines lie on the min faces.
  for (std::size_t k = 0; k < grid.size(); k += 3)
    EXPECT_TRUE(grid[k] == 0.0f || grid[k + 1] == 0.0f || grid[k + 2] == 0.0f);
  EXPECT_TRUE(gridOnBackFaces(box, 1e-4f, {5, 5, 5}).empty());  // too fine to draw
}

}  // namespace
}  // namespace sph::render
