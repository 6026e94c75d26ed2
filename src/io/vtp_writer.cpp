// Layout follows the VTK XML file formats ("VTK File Formats", VTK User's Guide): an XML header
// whose DataArrays point, by byte offset, into one raw appended block after an `_` marker; each
// array there is its UInt64 byte count followed by the bytes.
#include "io/vtp_writer.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "io/vtp_appended.hpp"
#include "sph/io/frame_writer.hpp"

namespace sph::io {

// Arrays are copied from memory as they are, so the host must already be what the header says.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "VTP writer assumes a little-endian host");
static_assert(std::numeric_limits<float>::is_iec559, "VTP Float32 must be IEEE 754");

std::vector<PointArrayTag> framePointArrays(bool torn) {
  std::vector<PointArrayTag> tags = {
      {"Float32", "velocity", 3, sizeof(float)},    {"Float32", "density", 1, sizeof(float)},
      {"Float32", "pressure", 1, sizeof(float)},    {"UInt8", "kind", 1, 1},
      {"Int32", "object", 1, sizeof(std::int32_t)}, {"UInt8", "surface", 1, 1},
      {"UInt32", "id", 1, sizeof(std::uint32_t)},
  };
  if (torn) tags.push_back({"UInt8", "torn", 1, 1});
  return tags;
}

void writePvtp(const std::vector<std::string>& pieces, bool torn, std::ostream& out) {
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\""
         " header_type=\"UInt64\">\n"
      << "  <PPolyData GhostLevel=\"0\">\n"
      << "    <PPointData Scalars=\"density\" Vectors=\"velocity\">\n";
  for (const PointArrayTag& tag : framePointArrays(torn)) {
    out << "      <PDataArray type=\"" << tag.type << "\" Name=\"" << tag.name << '"';
    if (tag.components > 1) out << " NumberOfComponents=\"" << tag.components << '"';
    out << "/>\n";
  }
  out << "    </PPointData>\n"
      << "    <PPoints>\n"
      << "      <PDataArray type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
      << "    </PPoints>\n";
  for (const std::string& piece : pieces) out << "    <Piece Source=\"" << piece << "\"/>\n";
  out << "  </PPolyData>\n</VTKFile>\n";
}

void writeVtp(const ParticleFrame& frame, std::ostream& out) {
  const std::uint64_t n = frame.size();
  // Frames made by hand may leave the surface flags out: they read as 0.
  std::vector<std::uint8_t> noSurface;
  if (frame.surface.size() != n) noSurface.assign(n, 0);
  const std::uint8_t* surface = noSurface.empty() ? frame.surface.data() : noSurface.data();
  // Tears are written only where the frame carries them.
  const bool torn = frame.torn.size() == n && n > 0;
  // Order matches the header sections below: PointData, then Points, then Verts.
  const auto dataOf = [&](const std::string& name) -> const void* {
    if (name == "velocity") return frame.velocity.data();
    if (name == "density") return frame.density.data();
    if (name == "pressure") return frame.pressure.data();
    if (name == "kind") return frame.kind.data();
    if (name == "object") return frame.object.data();
    if (name == "surface") return surface;
    if (name == "id") return frame.id.data();
    return frame.torn.data();
  };
  std::vector<AppendedArray> arrays;
  for (const PointArrayTag& tag : framePointArrays(torn))
    arrays.push_back({tag.type, tag.name, tag.components, n * tag.components * tag.bytes,
                      dataOf(tag.name), false, 0});
  const std::size_t firstPoints = arrays.size();
  arrays.push_back(
      {"Float32", "Points", 3, 3 * n * sizeof(float), frame.position.data(), false, 0});
  const std::size_t firstVerts = arrays.size();
  arrays.push_back({"Int64", "connectivity", 1, n * sizeof(std::int64_t), nullptr, true, 0});
  arrays.push_back({"Int64", "offsets", 1, n * sizeof(std::int64_t), nullptr, true, 1});

  const std::vector<std::uint64_t> offsets = appendedOffsets(arrays);

  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\""
         " header_type=\"UInt64\">\n"
      << "  <PolyData>\n"
      << "    <FieldData>\n"
      << "      <DataArray type=\"Float64\" Name=\"TIME\" NumberOfTuples=\"1\" format=\"ascii\">"
      << formatDouble(frame.time) << "</DataArray>\n"
      << "    </FieldData>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
      << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "      <PointData Scalars=\"density\" Vectors=\"velocity\">\n";
  for (std::size_t i = 0; i < firstPoints; ++i) {
    writeArrayTag(out, arrays[i], offsets[i], "        ");
  }
  out << "      </PointData>\n      <Points>\n";
  writeArrayTag(out, arrays[firstPoints], offsets[firstPoints], "        ");
  out << "      </Points>\n      <Verts>\n";
  for (std::size_t i = firstVerts; i < arrays.size(); ++i) {
    writeArrayTag(out, arrays[i], offsets[i], "        ");
  }
  out << "      </Verts>\n    </Piece>\n  </PolyData>\n";
  writeAppendedData(out, arrays);
}

}  // namespace sph::io
