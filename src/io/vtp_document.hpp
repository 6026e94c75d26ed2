// The binary VTK XML PolyData this project writes, read back: DataArrays with format="appended"
// whose offsets point into the raw block after the `_` marker, each block its byte count (UInt64,
// or UInt32 by header_type) followed by the bytes. Errors are InputErrors naming the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace sph::io {

class VtpDocument {
 public:
  // Parses the header; throws when it is not such a file or is cut short.
  VtpDocument(const std::string& bytes, const std::filesystem::path& file);

  // The <Piece>'s count `name` ("NumberOfPoints", "NumberOfPolys"), checked against what the
  // file could hold (each entry takes more than one byte).
  std::uint64_t pieceCount(const std::string& name) const;
  // The FieldData TIME, 0 when absent.
  double time() const;
  bool has(const std::string& array) const { return arrays_.count(array) != 0; }

  // Copies array `name` of `count` tuples of `components` values of `type` into `out`.
  template <typename T>
  void read(const std::string& name, const char* type, int components, std::uint64_t count,
            T* out) const {
    readBytes(name, type, components, count * std::uint64_t(components) * sizeof(T), out);
  }

 private:
  struct ArrayTag {
    std::string type;
    int components = 1;
    std::uint64_t offset = 0;
  };
  std::string startTag(const std::string& open) const;
  void readBytes(const std::string& name, const char* type, int components, std::uint64_t expected,
                 void* out) const;

  const std::string& bytes_;
  const std::filesystem::path& file_;
  std::string header_;
  std::size_t dataStart_ = 0;
  std::size_t countBytes_ = 8;
  std::map<std::string, ArrayTag> arrays_;
};

}  // namespace sph::io
