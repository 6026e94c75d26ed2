// Line geometry for the domain box and the uniform grid's cells, as pairs of points (x, y, z
// each) for GL_LINES. No GL.
#pragma once

#include <vector>

#include "camera.hpp"

namespace sph::render {

// The box's 12 edges.
std::vector<float> boxEdges(const Box3f& box);

// The grid's cell lines on the three faces of `box` away from `eye`, so that the grid is a
// backdrop behind the particles rather than a cage in front of them. Cells are `cellSize` wide,
// counted from box.min. Empty when a face would need more than `maxCells` cells along an axis
// (the lines would merge into a solid sheet).
std::vector<float> gridOnBackFaces(const Box3f& box, float cellSize, const Vec3f& eye,
                                   int maxCells = 256);

}  // namespace sph::render
