// What the offscreen render tests share: an OpenGL context of the picture's size and a renderer
// in it (the test is skipped, with the reason, where no context can be made), drawing a frame
// and reading it back, and where a world point lands in the picture.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "camera.hpp"
#include "offscreen_context.hpp"
#include "particle_renderer.hpp"

namespace sph::render::test {

class OffscreenFixture : public testing::Test {
 protected:
  OffscreenFixture(int width, int height) : width_(width), height_(height) {}

  // A subclass's SetUp calls this first and returns when IsSkipped().
  void SetUp() override {
    try {
      context_ = std::make_unique<OffscreenContext>(width_, height_);
    } catch (const ContextUnavailable& e) {
      GTEST_SKIP() << "no offscreen OpenGL context: " << e.what();
    }
    renderer_ = std::make_unique<ParticleRenderer>();
  }
  void TearDown() override {
    renderer_.reset();  // while its context is current
    context_.reset();
  }

  // Draws what the renderer holds; RGB bytes, top row first.
  std::vector<std::uint8_t> draw() {
    context_->bindForDrawing();
    renderer_->draw(camera_, settings_, width_, height_);
    context_->resolveForReading();
    return readRgbPixels(width_, height_);
  }
  std::vector<std::uint8_t> render(const ParticleFrame& frame) {
    renderer_->setParticles(frame);
    return draw();
  }

  // The index of the first of the three bytes of the pixel where the world point p appears.
  std::size_t pixelIndex(const Vec3f& p) const {
    const auto clip = transformPoint(
        multiply(camera_.projection(float(width_) / float(height_)), camera_.view()), p);
    const int x = static_cast<int>((clip[0] / clip[3] * 0.5f + 0.5f) * float(width_));
    const int y = static_cast<int>((0.5f - clip[1] / clip[3] * 0.5f) * float(height_));
    return 3 * (static_cast<std::size_t>(y) * std::size_t(width_) + std::size_t(x));
  }

  const int width_, height_;
  std::unique_ptr<OffscreenContext> context_;
  std::unique_ptr<ParticleRenderer> renderer_;
  OrbitCamera camera_;
  DrawSettings settings_;
};

}  // namespace sph::render::test
