// A closed triangle mesh of a fluid's surface (particle_surface.hpp), and what makes it fit for
// other tools: every edge shared by exactly two triangles, which run along it in opposite
// directions (closed, manifold, consistently oriented), and the volume it encloses.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sph::surface {

struct TriangleMesh {
  std::vector<float> vertices;           // x, y, z per vertex, m
  std::vector<std::uint32_t> triangles;  // three vertex indices each, counter-clockwise seen
                                         // from outside
  std::size_t vertexCount() const { return vertices.size() / 3; }
  std::size_t triangleCount() const { return triangles.size() / 3; }
};

struct MeshCheck {
  std::size_t openEdges = 0;         // used by one triangle only
  std::size_t overusedEdges = 0;     // by more than two (not manifold)
  std::size_t misorientedEdges = 0;  // two triangles running the same way along them
  double volume = 0.0;               // m³, by the divergence theorem; positive when outward
  bool watertight() const { return openEdges == 0 && overusedEdges == 0 && misorientedEdges == 0; }
};

MeshCheck checkMesh(const TriangleMesh& mesh);

}  // namespace sph::surface
