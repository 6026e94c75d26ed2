// Layout follows the VTK XML file formats ("VTK File Formats", VTK User's Guide): an XML header
// whose DataArrays point, by byte offset, into one raw appended block after an `_` marker; each
// array there is its UInt64 byte count followed by the bytes.
#include "io/vtp_writer.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "sph/io/frame_writer.hpp"

namespace sph::io {

// Arrays are copied from memory as they are, so the host must already be what the header says.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "VTP writer assumes a little-endian host");
static_assert(std::numeric_limits<float>::is_iec559, "VTP Float32 must be IEEE 754");

namespace {

struct AppendedArray {
  const char* type;
  const char* name;
  int components;
  std::uint64_t bytes;
  const void* data;  // unused for a sequence
  bool isSequence;   // Int64 values sequenceStart, sequenceStart + 1, ...
  std::int64_t sequenceStart;
};

// Verts need connectivity 0..n-1 and offsets 1..n; generating them in chunks avoids holding
// 16 bytes per particle just to write a counting sequence.
void writeInt64Sequence(std::ostream& out, std::int64_t start, std::uint64_t count) {
  constexpr std::uint64_t kChunk = 4096;
  std::vector<std::int64_t> chunk(static_cast<std::size_t>(std::min(count, kChunk)));
  for (std::uint64_t done = 0; done < count;) {
    const std::uint64_t len = std::min(count - done, kChunk);
    for (std::uint64_t i = 0; i < len; ++i) {
      chunk[i] = start + static_cast<std::int64_t>(done + i);
    }
    out.write(reinterpret_cast<const char*>(chunk.data()),
              static_cast<std::streamsize>(len * sizeof(std::int64_t)));
    done += len;
  }
}

void writeArrayTag(std::ostream& out, const AppendedArray& array, std::uint64_t offset,
                   const char* indent) {
  out << indent << "<DataArray type=\"" << array.type << "\" Name=\"" << array.name << '"';
  if (array.components > 1) out << " NumberOfComponents=\"" << array.components << '"';
  out << " format=\"appended\" offset=\"" << offset << "\"/>\n";
}

}  // namespace

void writeVtp(const ParticleFrame& frame, std::ostream& out) {
  const std::uint64_t n = frame.size();
  // Frames made by hand may leave the surface flags out: they read as 0.
  std::vector<std::uint8_t> noSurface;
  if (frame.surface.size() != n) noSurface.assign(n, 0);
  const std::uint8_t* surface = noSurface.empty() ? frame.surface.data() : noSurface.data();
  // Order matches the header sections below: PointData, then Points, then Verts.
  const std::vector<AppendedArray> arrays = {
      {"Float32", "velocity", 3, 3 * n * sizeof(float), frame.velocity.data(), false, 0},
      {"Float32", "density", 1, n * sizeof(float), frame.density.data(), false, 0},
      {"Float32", "pressure", 1, n * sizeof(float), frame.pressure.data(), false, 0},
      {"UInt8", "kind", 1, n * sizeof(std::uint8_t), frame.kind.data(), false, 0},
      {"Int32", "object", 1, n * sizeof(std::int32_t), frame.object.data(), false, 0},
      {"UInt8", "surface", 1, n * sizeof(std::uint8_t), surface, false, 0},
      {"UInt32", "id", 1, n * sizeof(std::uint32_t), frame.id.data(), false, 0},
      {"Float32", "Points", 3, 3 * n * sizeof(float), frame.position.data(), false, 0},
      {"Int64", "connectivity", 1, n * sizeof(std::int64_t), nullptr, true, 0},
      {"Int64", "offsets", 1, n * sizeof(std::int64_t), nullptr, true, 1},
  };
  constexpr std::size_t kFirstPoints = 7;
  constexpr std::size_t kFirstVerts = 8;

  std::vector<std::uint64_t> offsets(arrays.size());
  std::uint64_t offset = 0;
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    offsets[i] = offset;
    offset += sizeof(std::uint64_t) + arrays[i].bytes;
  }

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
  for (std::size_t i = 0; i < kFirstPoints; ++i) {
    writeArrayTag(out, arrays[i], offsets[i], "        ");
  }
  out << "      </PointData>\n      <Points>\n";
  writeArrayTag(out, arrays[kFirstPoints], offsets[kFirstPoints], "        ");
  out << "      </Points>\n      <Verts>\n";
  for (std::size_t i = kFirstVerts; i < arrays.size(); ++i) {
    writeArrayTag(out, arrays[i], offsets[i], "        ");
  }
  out << "      </Verts>\n    </Piece>\n  </PolyData>\n"
      << "  <AppendedData encoding=\"raw\">\n   _";

  for (const AppendedArray& array : arrays) {
    out.write(reinterpret_cast<const char*>(&array.bytes), sizeof array.bytes);
    if (array.isSequence) {
      writeInt64Sequence(out, array.sequenceStart, array.bytes / sizeof(std::int64_t));
    } else if (array.bytes > 0) {
      out.write(static_cast<const char*>(array.data), static_cast<std::streamsize>(array.bytes));
    }
  }
  out << "\n  </AppendedData>\n</VTKFile>\n";
}

}  // namespace sph::io
