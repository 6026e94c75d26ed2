// Reads binary little-endian PLY 1.0 as ply_writer.cpp writes it: a vertex element whose
// properties are found by name (so their order may differ), `comment time` and `comment step`.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "sph/io/frame_reader.hpp"
#include "io/frame_reader_support.hpp"

namespace sph::io {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "PLY reader assumes a little-endian host");

namespace {

struct Property {
  std::string type;  // float, uchar, int or uint (and their float32, uint8, ... synonyms)
  std::size_t offset = 0;
};

std::size_t typeBytes(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

// `value` as T where T can hold it; a value out of T's range (a corrupted file) becomes T's
// largest, or ±infinity for a float, rather than an undefined conversion.
template <typename T, typename V>
T converted(V value) {
  const double v = double(value);
  if constexpr (std::is_integral_v<T>) {
    if (!(v >= double(std::numeric_limits<T>::lowest()) &&
          v < double(std::numeric_limits<T>::max()) + 1.0))
      return std::numeric_limits<T>::max();
  } else if (std::abs(v) > double(std::numeric_limits<T>::max())) {
    return v > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
  }
  return static_cast<T>(value);
}

// The property's value at `record` as T, converting from the file's type.
template <typename T>
T valueAt(const char* record, const Property& p) {
  const char* at = record + p.offset;
  auto load = [at](auto value) {
    std::memcpy(&value, at, sizeof value);
    return converted<T>(value);
  };
  if (p.type == "float" || p.type == "float32") return load(float());
  if (p.type == "double" || p.type == "float64") return load(double());
  if (p.type == "uchar" || p.type == "uint8") return load(std::uint8_t());
  if (p.type == "char" || p.type == "int8") return load(std::int8_t());
  if (p.type == "short" || p.type == "int16") return load(std::int16_t());
  if (p.type == "ushort" || p.type == "uint16") return load(std::uint16_t());
  if (p.type == "int" || p.type == "int32") return load(std::int32_t());
  return load(std::uint32_t());
}

struct PlyHeader {
  std::size_t vertices = 0;
  std::size_t stride = 0;
  std::size_t dataStart = 0;
  std::map<std::string, Property> properties;
  double time = 0.0;
  std::uint64_t step = 0;
};

PlyHeader parseHeader(const std::string& bytes, const std::filesystem::path& file) {
  const std::string end = "end_header\n";
  const std::size_t endAt = bytes.find(end);
  if (bytes.compare(0, 4, "ply\n") != 0 || endAt == std::string::npos)
    throwBadFrame(file, "not a PLY file (expected 'ply' ... 'end_header')");
  PlyHeader header;
  header.dataStart = endAt + end.size();
  std::istringstream lines(bytes.substr(0, endAt));
  std::string line;
  bool inVertex = false;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "format") {
      std::string format;
      words >> format;
      if (format != "binary_little_endian")
        throwBadFrame(file, "PLY format '" + format + "', expected binary_little_endian");
    } else if (word == "comment") {
      std::string key;
      words >> key;
      if (key == "time") words >> header.time;
      if (key == "step") words >> header.step;
    } else if (word == "element") {
      std::string name;
      words >> name;
      inVertex = name == "vertex";
      if (inVertex) words >> header.vertices;
    } else if (word == "property" && inVertex) {
      std::string type, name;
      words >> type >> name;
      const std::size_t bytesOf = typeBytes(type);
      if (bytesOf == 0) throwBadFrame(file, "vertex property '" + name + "' has type " + type);
      header.properties[name] = {type, header.stride};
      header.stride += bytesOf;
    }
  }
  return header;
}

}  // namespace

ParticleFrame readPly(const std::string& bytes, const std::filesystem::path& file) {
  const PlyHeader header = parseHeader(bytes, file);
  const char* const required[] = {"x",       "y",        "z",    "vx",     "vy", "vz",
                                  "density", "pressure", "kind", "object", "id"};
  for (const char* name : required)
    if (!header.properties.count(name))
      throwBadFrame(file, std::string("no vertex property '") + name + "'");
  const std::size_t n = header.vertices;
  const std::size_t available = bytes.size() - header.dataStart;
  if (header.stride == 0 || n > available / header.stride)
    throwBadFrame(file, "truncated: " + std::to_string(n) + " vertices of " +
                            std::to_string(header.stride) + " bytes need " +
                            std::to_string(n * header.stride) + " bytes, the file holds " +
                            std::to_string(available));

  ParticleFrame frame;
  resizeFrame(frame, n);
  frame.time = header.time;
  frame.step = header.step;
  const auto& p = header.properties;
  const bool hasSurface = p.count("surface") != 0;
  const char* const xyz[] = {"x", "y", "z"};
  const char* const vxyz[] = {"vx", "vy", "vz"};
  for (std::size_t i = 0; i < n; ++i) {
    const char* record = bytes.data() + header.dataStart + i * header.stride;
    for (int c = 0; c < 3; ++c) {
      frame.position[3 * i + c] = valueAt<float>(record, p.at(xyz[c]));
      frame.velocity[3 * i + c] = valueAt<float>(record, p.at(vxyz[c]));
    }
    frame.density[i] = valueAt<float>(record, p.at("density"));
    frame.pressure[i] = valueAt<float>(record, p.at("pressure"));
    const unsigned kind = valueAt<unsigned>(record, p.at("kind"));
    requireValidKind(kind, i, file);
    frame.kind[i] = static_cast<std::uint8_t>(kind);
    frame.object[i] = valueAt<std::int32_t>(record, p.at("object"));
    frame.id[i] = valueAt<std::uint32_t>(record, p.at("id"));
    if (hasSurface) frame.surface[i] = valueAt<std::uint8_t>(record, p.at("surface"));
  }
  return frame;
}

}  // namespace sph::io
