#include "colour_bar.hpp"

#include <algorithm>

#include "colour_map.hpp"

namespace sph::render {

namespace {

void addVertex(std::vector<float>& out, float x, float y, const Rgb& c) {
  out.insert(out.end(), {x, y, c.r, c.g, c.b});
}

void addQuad(std::vector<float>& out, float x0, float y0, float x1, float y1, const Rgb& bottom,
             const Rgb& top) {
  addVertex(out, x0, y0, bottom);
  addVertex(out, x1, y0, bottom);
  addVertex(out, x1, y1, top);
  addVertex(out, x0, y0, bottom);
  addVertex(out, x1, y1, top);
  addVertex(out, x0, y1, top);
}

}  // namespace

ColourBarLayout colourBarLayout(int width) {
  const float pixelX = 2.0f / static_cast<float>(std::max(width, 1));
  const float right = 0.9f;
  return {right - 18.0f * pixelX, right, -0.6f, 0.6f};
}

std::vector<float> colourBarTriangles(int width, int height) {
  const ColourBarLayout bar = colourBarLayout(width);
  const float frameX = 2.0f * 2.0f / static_cast<float>(std::max(width, 1));
  const float frameY = 2.0f * 2.0f / static_cast<float>(std::max(height, 1));
  std::vector<float> out;
  const Rgb frame{0.9f, 0.9f, 0.92f};
  addQuad(out, bar.left - frameX, bar.bottom - frameY, bar.right + frameX, bar.top + frameY, frame,
          frame);
  // Finer than the map's control points, so the strip shows the map's own interpolation.
  constexpr int kSteps = 64;
  for (int s = 0; s < kSteps; ++s) {
    const float t0 = static_cast<float>(s) / kSteps, t1 = static_cast<float>(s + 1) / kSteps;
    const float y0 = bar.bottom + (bar.top - bar.bottom) * t0;
    const float y1 = bar.bottom + (bar.top - bar.bottom) * t1;
    addQuad(out, bar.left, y0, bar.right, y1, sequentialColour(t0), sequentialColour(t1));
  }
  return out;
}

}  // namespace sph::render
