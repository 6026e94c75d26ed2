#include "io/vtp_document.hpp"

#include <cstdlib>
#include <cstring>

#include "io/frame_reader_support.hpp"

namespace sph::io {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "VTP reader assumes a little-endian host");

namespace {

// The value of name="..." in an XML start tag; empty when absent.
std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t start = tag.find(key);
  if (start == std::string::npos) return {};
  const std::size_t begin = start + key.size();
  const std::size_t end = tag.find('"', begin);
  return end == std::string::npos ? std::string() : tag.substr(begin, end - begin);
}

}  // namespace

VtpDocument::VtpDocument(const std::string& bytes, const std::filesystem::path& file)
    : bytes_(bytes), file_(file) {
  const std::size_t appended = bytes_.find("<AppendedData");
  if (bytes_.compare(0, 5, "<?xml") != 0 || bytes_.find("<VTKFile") == std::string::npos ||
      appended == std::string::npos)
    throwBadFrame(file_, "not a VTK XML PolyData file with appended data (as sph writes)");
  header_ = bytes_.substr(0, appended);
  dataStart_ = bytes_.find('_', appended);
  if (dataStart_ == std::string::npos) throwBadFrame(file_, "no '_' before the appended data");
  ++dataStart_;
  // The writer closes the file last: without the closing tag the data may be cut short.
  if (bytes_.rfind("</VTKFile>") == std::string::npos || bytes_.rfind("</VTKFile>") < dataStart_)
    throwBadFrame(file_, "truncated: no closing </VTKFile> after the appended data");

  const std::string vtkTag = startTag("<VTKFile");
  if (attribute(vtkTag, "byte_order") != "LittleEndian")
    throwBadFrame(file_, "expected byte_order=\"LittleEndian\"");
  const std::string headerType = attribute(vtkTag, "header_type");
  countBytes_ = headerType == "UInt32" ? 4 : 8;
  if (headerType != "UInt32" && headerType != "UInt64" && !headerType.empty())
    throwBadFrame(file_, "expected header_type UInt32 or UInt64, not '" + headerType + "'");

  for (std::size_t at = header_.find("<DataArray"); at != std::string::npos;
       at = header_.find("<DataArray", at + 1)) {
    const std::string tag = header_.substr(at, header_.find('>', at) - at);
    if (attribute(tag, "format") != "appended") continue;
    ArrayTag array;
    array.type = attribute(tag, "type");
    const std::string components = attribute(tag, "NumberOfComponents");
    if (!components.empty()) array.components = std::atoi(components.c_str());
    array.offset = std::strtoull(attribute(tag, "offset").c_str(), nullptr, 10);
    arrays_[attribute(tag, "Name")] = array;
  }
}

std::uint64_t VtpDocument::pieceCount(const std::string& name) const {
  const std::string value = attribute(startTag("<Piece"), name);
  if (value.empty()) throwBadFrame(file_, "no <Piece " + name + "=...>");
  const std::uint64_t n = std::strtoull(value.c_str(), nullptr, 10);
  // Each entry takes more than one byte: a larger count is corrupt, not worth allocating.
  if (n > bytes_.size())
    throwBadFrame(file_, name + " " + value + " exceeds what the file can hold");
  return n;
}

double VtpDocument::time() const {
  const std::size_t tag = header_.find("Name=\"TIME\"");
  if (tag == std::string::npos) return 0.0;
  const std::size_t close = header_.find('>', tag);
  if (close == std::string::npos) return 0.0;
  return std::strtod(header_.c_str() + close + 1, nullptr);
}

std::string VtpDocument::startTag(const std::string& open) const {
  const std::size_t start = header_.find(open);
  if (start == std::string::npos) throwBadFrame(file_, "no " + open + "> element");
  return header_.substr(start, header_.find('>', start) - start);
}

void VtpDocument::readBytes(const std::string& name, const char* type, int components,
                            std::uint64_t expected, void* out) const {
  const auto found = arrays_.find(name);
  if (found == arrays_.end()) throwBadFrame(file_, "no DataArray named '" + name + "'");
  const ArrayTag& array = found->second;
  if (array.type != type || array.components != components)
    throwBadFrame(file_, "DataArray '" + name + "' is " + array.type + " x" +
                             std::to_string(array.components) + ", expected " + type + " x" +
                             std::to_string(components));
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

}  // namespace sph::io
