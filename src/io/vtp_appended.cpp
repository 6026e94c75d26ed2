#include "io/vtp_appended.hpp"

#include <algorithm>

namespace sph::io {

namespace {

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

}  // namespace

void writeArrayTag(std::ostream& out, const AppendedArray& array, std::uint64_t offset,
                   const char* indent) {
  out << indent << "<DataArray type=\"" << array.type << "\" Name=\"" << array.name << '"';
  if (array.components > 1) out << " NumberOfComponents=\"" << array.components << '"';
  out << " format=\"appended\" offset=\"" << offset << "\"/>\n";
}

std::vector<std::uint64_t> appendedOffsets(const std::vector<AppendedArray>& arrays) {
  std::vector<std::uint64_t> offsets(arrays.size());
  std::uint64_t offset = 0;
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    offsets[i] = offset;
    offset += sizeof(std::uint64_t) + arrays[i].bytes;
  }
  return offsets;
}

void writeAppendedData(std::ostream& out, const std::vector<AppendedArray>& arrays) {
  out << "  <AppendedData encoding=\"raw\">\n   _";
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
