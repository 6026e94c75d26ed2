// The objects drawn as their surfaces (sph/object_surface.hpp) rather than as particles: each
// frame places every mesh at its particles, leaves out the triangles where it has torn, and
// shades the rest with normals that stay smooth over a curved wall and sharp at a box's edges.
// No GL, so the tests can check what would be drawn.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "colour_map.hpp"
#include "sph/frame.hpp"
#include "sph/object_surface.hpp"

namespace sph::render {

// Triangles as drawn: per corner, position (3), normal (3) and colour (3), nine floats.
struct SurfaceTriangles {
  static constexpr std::size_t kFloatsPerCorner = 9;
  std::vector<float> corners;
  std::size_t open = 0;  // triangles left out where the surface has torn
  std::size_t triangleCount() const { return corners.size() / (3 * kFloatsPerCorner); }
};

// Corners whose faces meet at less than this keep one normal (a smooth wall); past it, each face
// its own (a box's edge).
constexpr float kCreaseDegrees = 40.0f;

SurfaceTriangles objectSurfaceTriangles(const std::vector<ObjectSurfaceMesh>& meshes,
                                        const ParticleFrame& frame);

}  // namespace sph::render
