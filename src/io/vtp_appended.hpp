// What the VTP writers share: DataArrays whose bytes follow the XML in one raw appended block,
// each its UInt64 byte count then the bytes ("VTK File Formats", VTK User's Guide).
#pragma once

#include <cstdint>
#include <ostream>
#include <vector>

namespace sph::io {

struct AppendedArray {
  const char* type;
  const char* name;
  int components;
  std::uint64_t bytes;
  const void* data;  // unused for a sequence
  bool isSequence;   // Int64 values sequenceStart, sequenceStart + 1, ...
  std::int64_t sequenceStart;
};

// Each array's offset into the appended block, in order.
std::vector<std::uint64_t> appendedOffsets(const std::vector<AppendedArray>& arrays);

void writeArrayTag(std::ostream& out, const AppendedArray& array, std::uint64_t offset,
                   const char* indent);

// `<AppendedData>` with every array's bytes, and the file's closing tags.
void writeAppendedData(std::ostream& out, const std::vector<AppendedArray>& arrays);

}  // namespace sph::io
