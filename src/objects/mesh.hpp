// Triangle meshes from OBJ and STL files, and their sampling into object particles.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sph/core/vec.hpp"

namespace sph::objects {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into vertices
};

// Reads Wavefront OBJ (v and f records; polygons are fanned into triangles; negative indices
// count from the end) or STL (ASCII or binary, told apart by content, not by extension).
// Throws InputError naming the file, and the line for text formats, on anything it cannot use.
TriangleMesh loadMesh(const std::filesystem::path& file);
// What loadMesh does with the file's bytes; `file` names the format (by its extension) and the
// mesh in messages.
TriangleMesh parseMesh(const std::string& bytes, const std::filesystem::path& file);

// The volume a closed mesh encloses by the divergence theorem, positive when its triangles
// wind outward (right hand).
double signedVolume(const TriangleMesh& mesh);

// Whether the mesh is closed: every edge is shared by exactly two triangles.
bool isClosed(const TriangleMesh& mesh);

// The mesh with every triangle's plane moved `distance` along its normal (negative: against
// it), vertices mitred at creases and corners, so that a layer of particles sampled from it
// lies at that distance from every face with no gap at the edges. Meant for distances small
// beside the features: a thinner part turns inside out.
TriangleMesh offsetAlongNormals(const TriangleMesh& mesh, double distance);

// Points with their outward normals.
struct SampledPoints {
  std::vector<Vec3> position;
  std::vector<Vec3> normal;  // unit; for solid samples, that of the nearest surface point
};

// Points on the surface about `spacing` apart (no two closer than ~0.5 spacing), covering every
// triangle, with the triangle's normal (outward for a consistently wound closed mesh).
SampledPoints sampleMeshSurface(const TriangleMesh& mesh, float spacing);

// Points of the cubic lattice of edge `spacing` inside a closed mesh (inside by the parity of
// ray crossings, robust to rays through edges and vertices). Throws InputError if not closed.
SampledPoints sampleMeshSolid(const TriangleMesh& mesh, float spacing);

// Whether p lies inside the closed mesh.
bool meshContains(const TriangleMesh& mesh, Vec3 p);

}  // namespace sph::objects
