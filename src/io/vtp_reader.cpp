// Reads the binary VTK XML PolyData that vtp_writer.cpp writes: DataArrays with
// format="appended" whose offsets point into the raw block after the `_` marker, each block its
// byte count (UInt64, or UInt32 by header_type) followed by the bytes.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

#include "sph/io/frame_reader.hpp"
#include "io/frame_reader_support.hpp"

namespace sph::io {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "VTP reader assumes a little-endian host");

namespace {

struct ArrayTag {
  std::string type;
  int components = 1;
  std::uint64_t offset = 0;
};

// The value of name="..." in an XML start tag; empty when absent.
std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t start = tag.find(key);
  if (start == std::string::npos) return {};
  const std::size_t begin = start + key.size();
  const std::size_t end = tag.find('"', begin);
  return end == std::string::npos ? std::string() : tag.substr(begin, end - begin);
}

class VtpParser {
 public:
  VtpParser(const std::string& bytes, const std::filesystem::path& file)
      : bytes_(bytes), file_(file) {}

  ParticleFrame parse() {
    const std::size_t appended = bytes_.find("<AppendedData");
    if (bytes_.compare(0, 5, "<?xml") != 0 || bytes_.find("<VTKFile") == std::string::npos ||
        appended == std::string::npos)
      throwBadFrame(file_, "not a VTK XML PolyData file with appended data (as sph writes)");
    const std::string header = bytes_.substr(0, appended);
    dataStart_ = bytes_.find('_', appended);
    if (dataStart_ == std::string::npos) throwBadFrame(file_, "no '_' before the appended data");
    ++dataStart_;
    // The writer closes the file last: without the closing tag the data may be cut short.
    if (bytes_.rfind("</VTKFile>") == std::string::npos || bytes_.rfind("</VTKFile>") < dataStart_)
      throwBadFrame(file_, "truncated: no closing </VTKFile> after the appended data");

    const std::string vtkTag = startTag(header, "<VTKFile");
    if (attribute(vtkTag, "byte_order") != "LittleEndian")
      throwBadFrame(file_, "expected byte_order=\"LittleEndian\"");
    const std::string headerType = attribute(vtkTag, "header_type");
    countBytes_ = headerType == "UInt32" ? 4 : 8;
    if (headerType != "UInt32" && headerType != "UInt64" && !headerType.empty())
      throwBadFrame(file_, "expected header_type UInt32 or UInt64, not '" + headerType + "'");

    const std::string points = attribute(startTag(header, "<Piece"), "NumberOfPoints");
    if (points.empty()) throwBadFrame(file_, "no <Piece NumberOfPoints=...>");
    n_ = std::strtoull(points.c_str(), nullptr, 10);
    // Each particle takes more than one byte: a larger count is corrupt, not worth allocating.
    if (n_ > bytes_.size())
      throwBadFrame(file_, "NumberOfPoints " + points + " exceeds what the file can hold");
    collectArrays(header);

    ParticleFrame frame;
    resizeFrame(frame, n_);
    frame.time = readTime(header);
    read("Points", "Float32", 3, frame.position.data());
    read("velocity", "Float32", 3, frame.velocity.data());
    read("density", "Float32", 1, frame.density.data());
    read("pressure", "Float32", 1, frame.pressure.data());
    read("kind", "UInt8", 1, frame.kind.data());
    read("object", "Int32", 1, frame.object.data());
    read("id", "UInt32", 1, frame.id.data());
    if (arrays_.count("surface")) read("surface", "UInt8", 1, frame.surface.data());
    for (std::size_t i = 0; i < n_; ++i) requireValidKind(frame.kind[i], i, file_);
    return frame;
  }

 private:
  std::string startTag(const std::string& header, const std::string& open) const {
    const std::size_t start = header.find(open);
    if (start == std::string::npos) throwBadFrame(file_, "no " + open + "> element");
    return header.substr(start, header.find('>', start) - start);
  }

  void collectArrays(const std::string& header) {
    for (std::size_t at = header.find("<DataArray"); at != std::string::npos;
         at = header.find("<DataArray", at + 1)) {
      const std::string tag = header.substr(at, header.find('>', at) - at);
      if (attribute(tag, "format") != "appended") continue;
      ArrayTag array;
      array.type = attribute(tag, "type");
      const std::string components = attribute(tag, "NumberOfComponents");
      if (!components.empty()) array.components = std::atoi(components.c_str());
      array.offset = std::strtoull(attribute(tag, "offset").c_str(), nullptr, 10);
      arrays_[attribute(tag, "Name")] = array;
    }
  }

  double readTime(const std::string& header) const {
    const std::size_t tag = header.find("Name=\"TIME\"");
    if (tag == std::string::npos) return 0.0;
    const std::size_t close = header.find('>', tag);
    if (close == std::string::npos) return 0.0;
    return std::strtod(header.c_str() + close + 1, nullptr);
  }

  template <typename T>
  void read(const std::string& name, const char* type, int components, T* out) const {
    const auto found = arrays_.find(name);
    if (found == arrays_.end()) throwBadFrame(file_, "no DataArray named '" + name + "'");
    const ArrayTag& array = found->second;
    if (array.type != type || array.components != components)
      throwBadFrame(file_, "DataArray '" + name + "' is " + array.type + " x" +
                               std::to_string(array.components) + ", expected " + type + " x" +
                               std::to_string(components));
    const std::uint64_t expected = n_ * std::uint64_t(components) * sizeof(T);
    const std::uint64_t begin = dataStart_ + array.offset;
    if (array.offset > bytes_.size() || begin + countBytes_ + expected > bytes_.size())
      throwBadFrame(file_, "truncated: DataArray '" + name + "' needs " + std::to_string(expected) +
                               " bytes at offset " + std::to_string(array.offset) +
                               " of the appended data");
    std::uint64_t count = 0;
    std::memcpy(&count, bytes_.data() + begin, countBytes_);
    if (count != expected)
      throwBadFrame(file_, "DataArray '" + name + "' holds " + std::to_string(count) +
                               " bytes, expected " + std::to_string(expected));
    if (expected > 0) std::memcpy(out, bytes_.data() + begin + countBytes_, expected);
  }

  const std::string& bytes_;
  const std::filesystem::path& file_;
  std::size_t dataStart_ = 0;
  std::size_t countBytes_ = 8;
  std::uint64_t n_ = 0;
  std::map<std::string, ArrayTag> arrays_;
};

}  // namespace

ParticleFrame readVtp(const std::string& bytes, const std::filesystem::path& file) {
  return VtpParser(bytes, file).parse();
}

}  // namespace sph::io
