// Renders known frames offscreen and checks the pixels: particles where they are, background
// where none are. Skipped, with the reason, where no offscreen context can be made.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <epoxy/gl.h>

#include "offscreen_fixture.hpp"
#include "particle_colours.hpp"

namespace sph::render {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

struct Pixel {
  int r, g, b;
};

class OffscreenRender : public test::OffscreenFixture {
 protected:
  OffscreenRender() : OffscreenFixture(kWidth, kHeight) {}
  void SetUp() override {
    OffscreenFixture::SetUp();
    if (IsSkipped()) return;
    // Looking along -z at the unit cube: x to the right, y up.
    camera_.target = {0.5f, 0.5f, 0.5f};
    camera_.distance = 2.6f;
    camera_.yaw = 0.0f;
    camera_.pitch = 0.0f;
    settings_.particleRadius = 0.03f;
    settings_.domain = {{0, 0, 0}, {1, 1, 1}};
  }

  // The pixel where the world point p appears.
  Pixel pixelAt(const std::vector<std::uint8_t>& rgb, const Vec3f& p) const {
    const std::size_t at = pixelIndex(p);
    return {rgb[at], rgb[at + 1], rgb[at + 2]};
  }

  bool isBackground(const Pixel& p) const {
    const Rgb& b = settings_.background;
    return p.r == toByte(b.r) && p.g == toByte(b.g) && p.b == toByte(b.b);
  }
};

void addParticle(ParticleFrame& f, const Vec3f& p, ParticleKind kind, int object) {
  f.id.push_back(static_cast<std::uint32_t>(f.id.size()));
  f.position.insert(f.position.end(), p.begin(), p.end());
  f.velocity.insert(f.velocity.end(), {0.0f, 0.0f, 0.0f});
  f.density.push_back(1000.0f);
  f.pressure.push_back(0.0f);
  f.kind.push_back(static_cast<std::uint8_t>(kind));
  f.object.push_back(object);
  f.surface.push_back(0);
}

// A block of fluid in the left half (x < 0.45) and a column of object particles at x = 0.8
// in the lower half.
ParticleFrame knownScene() {
  ParticleFrame f;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 14; ++j)
      for (int k = 0; k < 7; ++k)
        addParticle(f, {0.1f + 0.05f * i, 0.1f + 0.05f * j, 0.3f + 0.05f * k}, ParticleKind::Fluid,
                    -1);
  for (int j = 0; j < 6; ++j)
    addParticle(f, {0.8f, 0.1f + 0.05f * j, 0.5f}, ParticleKind::Object, 0);
  return f;
}

TEST_F(OffscreenRender, ParticlesWhereTheyAreBackgroundElsewhere) {
  const std::vector<std::uint8_t> rgb = render(knownScene());
  ASSERT_EQ(rgb.size(), std::size_t(3) * kWidth * kHeight);

  // Fluid: water blue in the middle of the block's face.
  const Pixel fluid = pixelAt(rgb, {0.25f, 0.45f, 0.6f});
  EXPECT_FALSE(isBackground(fluid));
  EXPECT_GT(fluid.b, fluid.r + 40) << fluid.r << "," << fluid.g << "," << fluid.b;
  // The object: its palette colour (red-dominant for object 0), below the middle on the right.
  const Pixel object = pixelAt(rgb, {0.8f, 0.2f, 0.5f});
  EXPECT_FALSE(isBackground(object));
  EXPECT_GT(object.r, object.b + 40) << object.r << "," << object.g << "," << object.b;
  // Nothing in the upper right or between the two.
  EXPECT_TRUE(isBackground(pixelAt(rgb, {0.8f, 0.85f, 0.5f})));
  EXPECT_TRUE(isBackground(pixelAt(rgb, {0.62f, 0.5f, 0.5f})));

  // The picture as a whole: a fair share covered, most of it not (an empty, black or uniform
  // image fails here).
  std::size_t covered = 0, left = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t at = 3 * (std::size_t(y) * kWidth + x);
      if (!isBackground({rgb[at], rgb[at + 1], rgb[at + 2]})) {
        ++covered;
        if (x < kWidth / 2) ++left;
      }
    }
  EXPECT_GT(covered, std::size_t(kWidth * kHeight) / 20);
  EXPECT_LT(covered, std::size_t(kWidth * kHeight) / 2);
  EXPECT_GT(left, covered * 8 / 10) << "the fluid block is on the left";
}

TEST_F(OffscreenRender, EmptyFrameIsAllBackground) {
  const std::vector<std::uint8_t> rgb = render(ParticleFrame{});
  for (std::size_t at = 0; at < rgb.size(); at += 3)
    ASSERT_TRUE(isBackground({rgb[at], rgb[at + 1], rgb[at + 2]})) << "pixel " << at / 3;
}

TEST_F(OffscreenRender, NearerSphereHidesTheOneBehind) {
  ParticleFrame f;
  addParticle(f, {0.5f, 0.5f, 0.9f}, ParticleKind::Object, 0);  // nearer the eye (at z = 3.1)
  addParticle(f, {0.5f, 0.5f, 0.1f}, ParticleKind::Fluid, -1);  // drawn after, behind it
  settings_.particleRadius = 0.08f;
  const Pixel centre = pixelAt(render(f), {0.5f, 0.5f, 0.9f});
  EXPECT_GT(centre.r, centre.b) << "the object in front, not the fluid behind";
}

TEST_F(OffscreenRender, HiddenKindsAreNotDrawn) {
  settings_.show.fluid = false;
  const std::vector<std::uint8_t> rgb = render(knownScene());
  EXPECT_TRUE(isBackground(pixelAt(rgb, {0.25f, 0.45f, 0.6f})));
  EXPECT_FALSE(isBackground(pixelAt(rgb, {0.8f, 0.2f, 0.5f})));
}

TEST_F(OffscreenRender, ColourBarShowsTheMapForQuantities) {
  settings_.colour = ColourMode::Density;
  settings_.range = ValueRange{990.0f, 1010.0f};
  const std::vector<std::uint8_t> rgb = render(ParticleFrame{});
  // The strip's right edge is at 0.9 in device coordinates, 18 pixels wide, from -0.6 to 0.6.
  const int x = static_cast<int>((0.9f * 0.5f + 0.5f) * kWidth) - 5;
  auto at = [&](float ndcY) {
    const int y = static_cast<int>((0.5f - 0.5f * ndcY) * kHeight);
    const std::size_t i = 3 * (std::size_t(y) * kWidth + x);
    return Pixel{rgb[i], rgb[i + 1], rgb[i + 2]};
  };
  const Pixel top = at(0.55f), bottom = at(-0.55f);
  EXPECT_GT(top.r + top.g, 350) << "yellow at the top";
  EXPECT_GT(bottom.b, bottom.g + 30) << "violet at the bottom";
}

// The fluid written straight into the GL buffers, as CUDA–OpenGL interop does on a GPU (here
// from the host, in another order than by id), with the solids behind it, draws the picture
// the host path draws.
TEST_F(OffscreenRender, FluidWrittenIntoTheBuffersDrawsAsTheHostPath) {
  const ParticleFrame whole = knownScene();
  ParticleFrame solids;
  std::vector<float> fluidPositions;
  std::vector<float> fluidDensities;
  for (std::size_t i = whole.size(); i-- > 0;) {  // reversed
    if (whole.kind[i] != std::uint8_t(ParticleKind::Fluid)) continue;
    fluidPositions.insert(fluidPositions.end(), &whole.position[3 * i], &whole.position[3 * i + 3]);
    fluidPositions.push_back(1.0f);
    fluidDensities.push_back(990.0f + float(i % 21));
  }
  for (std::size_t i = 0; i < whole.size(); ++i)
    if (whole.kind[i] != std::uint8_t(ParticleKind::Fluid))
      addParticle(solids,
                  {whole.position[3 * i], whole.position[3 * i + 1], whole.position[3 * i + 2]},
                  ParticleKind(whole.kind[i]), whole.object[i]);
  ParticleFrame byHost = whole;
  std::size_t f = fluidDensities.size();
  for (std::size_t i = 0; i < whole.size(); ++i)
    if (whole.kind[i] == std::uint8_t(ParticleKind::Fluid)) byHost.density[i] = fluidDensities[--f];

  settings_.colour = ColourMode::Density;
  settings_.range = ValueRange{990.0f, 1010.0f};
  const std::vector<std::uint8_t> expected = render(byHost);

  const std::size_t fluid = fluidDensities.size();
  renderer_->reserve(whole.size());
  const FluidColourTable table = fluidColourTable(settings_.colour, *settings_.range, true);
  std::vector<std::uint8_t> rgba(4 * fluid);
  colourFromTable(table, fluidDensities.data(), fluid, rgba.data());
  glBindBuffer(GL_ARRAY_BUFFER, renderer_->positionBuffer().name);
  glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(fluidPositions.size() * sizeof(float)),
                  fluidPositions.data());
  glBindBuffer(GL_ARRAY_BUFFER, renderer_->colourBuffer().name);
  glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(rgba.size()), rgba.data());
  renderer_->setParticlesBehindFluid(fluid, *settings_.range, solids);
  EXPECT_EQ(renderer_->particleCount(), whole.size());
  const std::vector<std::uint8_t> drawn = draw();

  std::size_t covered = 0, differing = 0;
  for (std::size_t at = 0; at < drawn.size(); at += 3) {
    if (!isBackground({expected[at], expected[at + 1], expected[at + 2]})) ++covered;
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(drawn[at + c]) - int(expected[at + c])) > 3) {
        ++differing;
        break;
      }
  }
  EXPECT_GT(covered, std::size_t(kWidth * kHeight) / 20);
  // Equal depths may resolve the other way where spheres touch: a few edge pixels.
  EXPECT_LT(differing, covered / 50) << differing << " of " << covered << " covered pixels differ";
  // The object behind the fluid is still there, in its own colour.
  const Pixel object = pixelAt(drawn, {0.8f, 0.2f, 0.5f});
  EXPECT_GT(object.r, object.b + 40);
  // More than the reserved room is refused.
  EXPECT_THROW(renderer_->setParticlesBehindFluid(fluid + 1, {}, whole), std::invalid_argument);
}

TEST_F(OffscreenRender, PositionBufferHoldsFourFloatsPerParticle) {
  const ParticleFrame frame = knownScene();
  renderer_->setParticles(frame);
  const auto buffer = renderer_->positionBuffer();
  EXPECT_NE(buffer.name, 0u);
  EXPECT_EQ(buffer.capacity, frame.size());
  renderer_->setParticles(ParticleFrame{});  // shrinking keeps the buffer
  EXPECT_EQ(renderer_->positionBuffer().capacity, frame.size());
}

}  // namespace
}  // namespace sph::render
