#include "sph/io/object_surface_file.hpp"

#include <cstdint>
#include <vector>

#include "io/vtp_appended.hpp"
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

}  // namespace sph::io
