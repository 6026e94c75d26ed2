// An object's surface drawn as triangles that follow its particles: each vertex is tied to three
// of the object's particles and keeps its place in their triangle, so the surface moves, turns
// and deforms with them, and opens where the object tears. `Simulation::objectSurfaces()` gives
// them for the scene's built-in objects; `sph run` writes them once, to `object_surfaces.vtp`.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/frame.hpp"

namespace sph {

struct ObjectSurfaceMesh {
  std::int32_t object = 0;               // the object's index, as in ParticleFrame::object
  std::vector<float> restPosition;       // x, y, z per vertex, m: the surface as built
  std::vector<std::uint32_t> triangles;  // three vertices each, wound outward (right hand)
  std::vector<std::uint32_t> anchor;     // three particle ids per vertex
  std::vector<float> coordinate;         // α, β, h per vertex (anchoredPoint)

  std::size_t vertexCount() const { return restPosition.size() / 3; }
  std::size_t triangleCount() const { return triangles.size() / 3; }
};

// The point x0 + α (x1 − x0) + β (x2 − x0) + h n̂, n̂ the unit normal of the triangle (x0, x1, x2)
// by the right hand: a rigid motion of the three moves it rigidly; a stretch stretches it.
inline void anchoredPoint(const float* x0, const float* x1, const float* x2, const float* abh,
                          float* out) {
  float e1[3], e2[3];
  for (int a = 0; a < 3; ++a) {
    e1[a] = x1[a] - x0[a];
    e2[a] = x2[a] - x0[a];
  }
  float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0]};
  const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const float scale = length > 0.0f ? abh[2] / length : 0.0f;
  for (int a = 0; a < 3; ++a) out[a] = x0[a] + abh[0] * e1[a] + abh[1] * e2[a] + scale * n[a];
}

struct PlacedSurface {
  std::vector<float> position;     // x, y, z per vertex, m
  std::vector<std::uint8_t> open;  // per triangle: 1 where the surface is torn or incomplete
};

// The mesh's vertices at the frame's particles (in any order). A triangle is open where all three
// of its vertices hang on particles whose springs broke (ParticleFrame::torn), and where a particle
// it hangs on is missing from the frame (its vertices are then left at rest).
PlacedSurface placeObjectSurface(const ObjectSurfaceMesh& mesh, const ParticleFrame& frame);

}  // namespace sph
