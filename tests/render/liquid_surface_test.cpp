// The liquid view of a resting block of fluid, drawn offscreen: its top reads flat, its
// normals hold no particle-sized bumps, it covers what the particles cover, and the thickness
// it absorbs through is the block's. Skipped, with the reason, where no offscreen context can
// be made.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "liquid_surface.hpp"
#include "offscreen_fixture.hpp"

namespace sph::render {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr float kSpacing = 0.02f;
constexpr int kCells[3] = {30, 10, 30};  // a block 0.6 m wide and deep, 0.2 m high

ParticleFrame restingBlock() {
  ParticleFrame f;
  for (int i = 0; i < kCells[0]; ++i)
    for (int j = 0; j < kCells[1]; ++j)
      for (int k = 0; k < kCells[2]; ++k) {
        f.id.push_back(static_cast<std::uint32_t>(f.id.size()));
        f.position.insert(f.position.end(),
                          {kSpacing * (float(i) + 0.5f), kSpacing * (float(j) + 0.5f),
                           kSpacing * (float(k) + 0.5f)});
        f.velocity.insert(f.velocity.end(), {0.0f, 0.0f, 0.0f});
        f.density.push_back(1000.0f);
        f.pressure.push_back(0.0f);
        f.kind.push_back(static_cast<std::uint8_t>(ParticleKind::Fluid));
        f.object.push_back(-1);
        f.surface.push_back(0);
      }
  return f;
}

float topOfBlock() {
  return kSpacing * float(kCells[1]);
}

class LiquidView : public test::OffscreenFixture {
 protected:
  LiquidView() : OffscreenFixture(kWidth, kHeight) {}
  void SetUp() override {
    OffscreenFixture::SetUp();
    if (IsSkipped()) return;
    // Looking down at the middle of the block's top, steeply, from the front.
    camera_.target = {0.3f, topOfBlock(), 0.3f};
    camera_.distance = 0.7f;
    camera_.yaw = 0.0f;
    camera_.pitch = 1.0f;
    settings_.particleRadius = 0.5f * kSpacing;
    settings_.look = Look::Liquid;
    settings_.showColourBar = false;
    renderer_->setParticles(restingBlock());
  }

  // The world point each pixel's smoothed depth stands for (rows from the bottom); y = NaN
  // where no liquid is.
  std::vector<std::array<float, 3>> surfacePoints() const {
    const std::vector<float> depth = renderer_->liquidSurface()->smoothedDepth();
    const Mat4f view = camera_.view();
    const Mat4f projection = camera_.projection(float(kWidth) / float(kHeight));
    std::vector<std::array<float, 3>> points(depth.size());
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const std::size_t at = std::size_t(y) * kWidth + std::size_t(x);
        const float z = depth[at];
        if (!(z > 0.0f)) {
          points[at] = {NAN, NAN, NAN};
          continue;
        }
        const float ndcX = 2.0f * (float(x) + 0.5f) / kWidth - 1.0f;
        const float ndcY = 2.0f * (float(y) + 0.5f) / kHeight - 1.0f;
        const float eye[3] = {ndcX * z / projection[0], ndcY * z / projection[5], -z};
        // The view is a rotation R and a translation t: world = Rᵀ (eye − t).
        std::array<float, 3> world{};
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) world[r] += view[4 * r + c] * (eye[c] - view[12 + c]);
        points[at] = world;
      }
    return points;
  }

  // The middle fifth of the image each way, which sees only the block's top.
  template <class Visit>
  void forMiddle(Visit&& visit) const {
    for (int y = 2 * kHeight / 5; y < 3 * kHeight / 5; ++y)
      for (int x = 2 * kWidth / 5; x < 3 * kWidth / 5; ++x) visit(x, y);
  }

  // The largest angle (degrees) between the surface's normal and +y over the middle of the
  // image, from the world points of neighbouring pixels.
  double steepestNormal() const {
    const std::vector<std::array<float, 3>> p = surfacePoints();
    double steepest = 0.0;
    forMiddle([&](int x, int y) {
      const auto& o = p[std::size_t(y) * kWidth + std::size_t(x)];
      const auto& right = p[std::size_t(y) * kWidth + std::size_t(x + 1)];
      const auto& up = p[std::size_t(y + 1) * kWidth + std::size_t(x)];
      const double a[3] = {right[0] - o[0], right[1] - o[1], right[2] - o[2]};
      const double b[3] = {up[0] - o[0], up[1] - o[1], up[2] - o[2]};
      const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                           a[0] * b[1] - a[1] * b[0]};
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const double angle = std::acos(std::min(1.0, std::abs(n[1]) / length)) * 180.0 / M_PI;
      steepest = std::max(steepest, angle);
    });
    return steepest;
  }
};

TEST_F(LiquidView, TheTopOfARestingBlockIsFlatWithinHalfASpacing) {
  draw();
  const std::vector<std::array<float, 3>> p = surfacePoints();
  float lowest = 1e9f, highest = -1e9f;
  int liquid = 0;
  forMiddle([&](int x, int y) {
    const float height = p[std::size_t(y) * kWidth + std::size_t(x)][1];
    if (std::isnan(height)) return;
    ++liquid;
    lowest = std::min(lowest, height);
    highest = std::max(highest, height);
  });
  RecordProperty("top_lowest_over_spacing", std::to_string((lowest - topOfBlock()) / kSpacing));
  RecordProperty("top_highest_over_spacing", std::to_string((highest - topOfBlock()) / kSpacing));
  EXPECT_EQ(liquid, (kWidth / 5) * (kHeight / 5));  // all of it is the block's top
  EXPECT_LT(highest - lowest, 0.5f * kSpacing);
  // Where the fluid ends: half a spacing above its top layer of particles.
  EXPECT_GT(lowest, topOfBlock() - 0.25f * kSpacing);
  EXPECT_LT(highest, topOfBlock() + 0.25f * kSpacing);
}

TEST_F(LiquidView, TheDefaultSmoothingLeavesNoParticleSizedBumps) {
  settings_.liquid.smoothingPasses = 0;
  draw();
  const double raw = steepestNormal();
  settings_.liquid = LiquidStyle{};
  draw();
  const double smoothed = steepestNormal();
  RecordProperty("steepest_raw_degrees", std::to_string(raw));
  RecordProperty("steepest_smoothed_degrees", std::to_string(smoothed));
  EXPECT_GT(raw, 30.0);  // the spheres' bumps, unsmoothed
  EXPECT_LT(smoothed, 2.0);
}

TEST_F(LiquidView, CoversThePixelsTheParticlesCoverWithin5Percent) {
  const auto covered = [&](const std::vector<std::uint8_t>& rgb) {
    const Rgb& b = settings_.background;
    std::size_t count = 0;
    for (std::size_t i = 0; i < rgb.size(); i += 3)
      if (rgb[i] != toByte(b.r) || rgb[i + 1] != toByte(b.g) || rgb[i + 2] != toByte(b.b)) ++count;
    return count;
  };
  camera_.distance = 1.6f;  // the whole block in the picture, background around it
  const std::size_t liquid = covered(draw());
  settings_.look = Look::Particles;
  const std::size_t particles = covered(draw());
  RecordProperty("liquid_pixels", std::to_string(liquid));
  RecordProperty("particle_pixels", std::to_string(particles));
  ASSERT_GT(particles, std::size_t(kWidth * kHeight / 10));
  EXPECT_NEAR(double(liquid), double(particles), 0.05 * double(particles));
}

// Each sphere's chord counts its particle's share of the volume: averaged over the rays of the
// middle of the picture, the thickness is the length of each ray within the block.
TEST_F(LiquidView, TheThicknessAlongTheRaysIsTheBlocksDepthAlongThem) {
  draw();
  const std::vector<float> thickness = renderer_->liquidSurface()->thickness();
  const Mat4f view = camera_.view();
  const Mat4f projection = camera_.projection(float(kWidth) / float(kHeight));
  const Vec3f eye = camera_.eye();
  const float hi[3] = {kSpacing * kCells[0], kSpacing * kCells[1], kSpacing * kCells[2]};
  double measured = 0.0, expected = 0.0;
  forMiddle([&](int x, int y) {
    measured += thickness[std::size_t(y) * kWidth + std::size_t(x)];
    // The pixel's ray in world space, through the slab test against the block's box.
    const float ndc[2] = {2.0f * (float(x) + 0.5f) / kWidth - 1.0f,
                          2.0f * (float(y) + 0.5f) / kHeight - 1.0f};
    const float along[3] = {ndc[0] / projection[0], ndc[1] / projection[5], -1.0f};
    float direction[3] = {0, 0, 0};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) direction[r] += view[4 * r + c] * along[c];
    float enter = 0.0f, leave = 1e9f;
    for (int a = 0; a < 3; ++a) {
      const float t0 = (0.0f - eye[a]) / direction[a], t1 = (hi[a] - eye[a]) / direction[a];
      enter = std::max(enter, std::min(t0, t1));
      leave = std::min(leave, std::max(t0, t1));
    }
    const float length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                   direction[2] * direction[2]);
    expected += std::max(0.0f, leave - enter) * length;
  });
  RecordProperty("mean_thickness_over_path", std::to_string(measured / expected));
  EXPECT_NEAR(measured, expected, 0.05 * expected);
}

}  // namespace
}  // namespace sph::render
