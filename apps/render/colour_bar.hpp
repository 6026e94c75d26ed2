// The colour bar's geometry: a vertical strip of the sequential map (low at the bottom) in a
// dark frame at the right of the picture, as triangles in normalised device coordinates with a
// colour per vertex (x, y, r, g, b). No GL.
#pragma once

#include <vector>

namespace sph::render {

struct ColourBarLayout {
  float left, right, bottom, top;  // the strip, in normalised device coordinates
};

// The strip's place for a viewport this many pixels wide: 18 pixels wide, 60 % of the height, its
// right edge 5 % of the width from the border.
ColourBarLayout colourBarLayout(int width);

std::vector<float> colourBarTriangles(int width, int height);

}  // namespace sph::render
