#include <cstdint>
#include <string>
#include <vector>

#include "io/frame_reader_support.hpp"
#include "io/vtp_document.hpp"
#include "sph/io/object_surface_file.hpp"

namespace sph::io {

std::vector<ObjectSurfaceMesh> parseObjectSurfaces(const std::string& bytes,
                                                   const std::filesystem::path& file) {
  const VtpDocument vtp(bytes, file);
  const std::uint64_t n = vtp.pieceCount("NumberOfPoints");
  const std::uint64_t polys = vtp.pieceCount("NumberOfPolys");
  struct {
    std::vector<float> position, coordinate;
    std::vector<std::uint32_t> anchor;
    std::vector<std::int32_t> object;
    std::vector<std::int64_t> connectivity, offsets;
  } j;
  j.position.resize(3 * n);
  j.coordinate.resize(3 * n);
  j.anchor.resize(3 * n);
  j.object.resize(n);
  j.connectivity.resize(3 * polys);
  j.offsets.resize(polys);
  vtp.read("Points", "Float32", 3, n, j.position.data());
  vtp.read("coordinate", "Float32", 3, n, j.coordinate.data());
  vtp.read("anchor", "UInt32", 3, n, j.anchor.data());
  vtp.read("object", "Int32", 1, n, j.object.data());
  vtp.read("connectivity", "Int64", 1, 3 * polys, j.connectivity.data());
  vtp.read("offsets", "Int64", 1, polys, j.offsets.data());

  // Vertices come object by object; each object's triangles use its own vertices only.
  std::vector<ObjectSurfaceMesh> out;
  std::vector<std::uint64_t> firstVertex;
  for (std::uint64_t v = 0; v < n; ++v) {
    if (out.empty() || out.back().object != j.object[v]) {
      out.emplace_back().object = j.object[v];
      firstVertex.push_back(v);
    }
    ObjectSurfaceMesh& s = out.back();
    s.restPosition.insert(s.restPosition.end(), &j.position[3 * v], &j.position[3 * v] + 3);
    s.coordinate.insert(s.coordinate.end(), &j.coordinate[3 * v], &j.coordinate[3 * v] + 3);
    s.anchor.insert(s.anchor.end(), &j.anchor[3 * v], &j.anchor[3 * v] + 3);
  }
  std::size_t surface = 0;
  for (std::uint64_t t = 0; t < polys; ++t) {
    if (j.offsets[t] != std::int64_t(3 * (t + 1)))
      throwBadFrame(file, "polygon " + std::to_string(t) + " is not a triangle");
    const std::int64_t* v = &j.connectivity[3 * t];
    while (surface < out.size() &&
           v[0] >= std::int64_t(firstVertex[surface] + out[surface].vertexCount()))
      ++surface;
    for (int a = 0; a < 3; ++a) {
      const bool inside = surface < out.size() && v[a] >= std::int64_t(firstVertex[surface]) &&
                          v[a] < std::int64_t(firstVertex[surface] + out[surface].vertexCount());
      if (!inside)
        throwBadFrame(file, "triangle " + std::to_string(t) + " joins vertex " +
                                std::to_string(v[a]) +
                                ", expected one of its object's vertices, after the previous ones");
      out[surface].triangles.push_back(std::uint32_t(v[a] - std::int64_t(firstVertex[surface])));
    }
  }
  return out;
}

std::vector<ObjectSurfaceMesh> readObjectSurfaces(const std::filesystem::path& file) {
  return parseObjectSurfaces(readFileBytes(file), file);
}

}  // namespace sph::io
