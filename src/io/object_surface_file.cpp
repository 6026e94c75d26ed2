#include "sph/io/object_surface_file.hpp"

#include <cstdint>
#include <vector>

#include "io/frame_reader_support.hpp"
#include "io/vtp_appended.hpp"
#include "io/vtp_document.hpp"
#include "sph/io/frame_writer.hpp"

namespace sph::io {

namespace {

// Every surface's vertices and triangles in one list, triangles renumbered.
struct Joined {
  std::vector<float> position, coordinate;
  std::vector<std::uint32_t> anchor;
  std::vector<std::int32_t> object;
  std::vector<std::int64_t> connectivity, offsets;
};

Joined join(const std::vector<ObjectSurfaceMesh>& surfaces) {
  Joined j;
  for (const ObjectSurfaceMesh& s : surfaces) {
    const auto first = std::int64_t(j.object.size());
    j.position.insert(j.position.end(), s.restPosition.begin(), s.restPosition.end());
    j.coordinate.insert(j.coordinate.end(), s.coordinate.begin(), s.coordinate.end());
    j.anchor.insert(j.anchor.end(), s.anchor.begin(), s.anchor.end());
    j.object.insert(j.object.end(), s.vertexCount(), s.object);
    for (std::uint32_t v : s.triangles) {
      j.connectivity.push_back(first + v);
      if (j.connectivity.size() % 3 == 0) j.offsets.push_back(std::int64_t(j.connectivity.size()));
    }
  }
  return j;
}

}  // namespace

void writeObjectSurfaces(const std::vector<ObjectSurfaceMesh>& surfaces,
                         const std::filesystem::path& file) {
  const Joined j = join(surfaces);
  const std::uint64_t n = j.object.size(), polys = j.offsets.size();
  const std::vector<AppendedArray> arrays = {
      {"Int32", "object", 1, n * sizeof(std::int32_t), j.object.data(), false, 0},
      {"UInt32", "anchor", 3, 3 * n * sizeof(std::uint32_t), j.anchor.data(), false, 0},
      {"Float32", "coordinate", 3, 3 * n * sizeof(float), j.coordinate.data(), false, 0},
      {"Float32", "Points", 3, 3 * n * sizeof(float), j.position.data(), false, 0},
      {"Int64", "connectivity", 1, 3 * polys * sizeof(std::int64_t), j.connectivity.data(), false,
       0},
      {"Int64", "offsets", 1, polys * sizeof(std::int64_t), j.offsets.data(), false, 0},
  };
  const std::vector<std::uint64_t> offsets = appendedOffsets(arrays);
  writeFileAtomically(file, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\""
           " header_type=\"UInt64\">\n"
        << "  <PolyData>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\""
        << " NumberOfStrips=\"0\" NumberOfPolys=\"" << polys << "\">\n"
        << "      <PointData Scalars=\"object\">\n";
    for (std::size_t i = 0; i < 3; ++i) writeArrayTag(out, arrays[i], offsets[i], "        ");
    out << "      </PointData>\n      <Points>\n";
    writeArrayTag(out, arrays[3], offsets[3], "        ");
    out << "      </Points>\n      <Polys>\n";
    for (std::size_t i = 4; i < 6; ++i) writeArrayTag(out, arrays[i], offsets[i], "        ");
    out << "      </Polys>\n    </Piece>\n  </PolyData>\n";
    writeAppendedData(out, arrays);
  });
}

std::vector<ObjectSurfaceMesh> parseObjectSurfaces(const std::string& bytes,
                                                   const std::filesystem::path& file) {
  const VtpDocument vtp(bytes, file);
  const std::uint64_t n = vtp.pieceCount("NumberOfPoints");
  const std::uint64_t polys = vtp.pieceCount("NumberOfPolys");
  Joined j;
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
