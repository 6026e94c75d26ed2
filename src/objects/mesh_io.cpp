// Reading triangle meshes from Wavefront OBJ and STL (ASCII and binary) files.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>

#include "objects/mesh.hpp"
#include "sph/error.hpp"

namespace sph::objects {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& file, const std::string& what) {
  throw InputError(file.string() + ": " + what);
}

[[noreturn]] void failAt(const fs::path& file, std::size_t line, const std::string& what) {
  throw InputError(file.string() + ":" + std::to_string(line) + ": " + what);
}

std::string readWholeFile(const fs::path& file) {
  std::error_code error;
  if (!fs::exists(file, error)) fail(file, "file does not exist");
  if (fs::is_directory(file, error)) fail(file, "is a directory, not a mesh file");
  // A pipe would block the read forever, and a device or a sparse file never end.
  if (!fs::is_regular_file(file, error))
    fail(file, "is not a regular file (a device, a pipe or a socket), not a mesh file");
  constexpr std::uintmax_t kLargest = std::uintmax_t(1) << 30;
  const std::uintmax_t size = fs::file_size(file, error);
  if (!error && size > kLargest)
    fail(file, "is " + std::to_string(size) + " bytes; meshes over 1 GiB are refused");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "cannot be opened for reading");
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

// A text file split into lines, with '\r' and '#' comments removed and words split on blanks.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  bool next() {
    if (position_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', position_), text_.size());
    line_ = text_.substr(position_, end - position_);
    position_ = end + 1;
    ++number_;
    const std::size_t hash = line_.find('#');
    if (hash != std::string_view::npos) line_ = line_.substr(0, hash);
    words_.clear();
    std::size_t i = 0;
    while (i < line_.size()) {
      while (i < line_.size() && std::isspace(static_cast<unsigned char>(line_[i]))) ++i;
      const std::size_t start = i;
      while (i < line_.size() && !std::isspace(static_cast<unsigned char>(line_[i]))) ++i;
      if (i > start) words_.push_back(line_.substr(start, i - start));
    }
    return true;
  }

  std::size_t number() const { return number_; }
  const std::vector<std::string_view>& words() const { return words_; }

  // The line as written, trimmed and shortened, for quoting in messages.
  std::string quoted() const {
    constexpr std::size_t kMaxLength = 60;
    std::string text;
    for (std::string_view word : words_) text += (text.empty() ? "" : " ") + std::string(word);
    if (text.size() > kMaxLength) text = text.substr(0, kMaxLength - 3) + "...";
    return "'" + text + "'";
  }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  std::size_t number_ = 0;
  std::string_view line_;
  std::vector<std::string_view> words_;
};

bool parseFloat(std::string_view word, float& value) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  return error == std::errc() && end == word.data() + word.size() && std::isfinite(value);
}

// Parses words[first..first+3) as a point; false if they are missing or not finite numbers.
bool parsePoint(const std::vector<std::string_view>& words, std::size_t first, Vec3& p) {
  return words.size() >= first + 3 && parseFloat(words[first], p.x) &&
         parseFloat(words[first + 1], p.y) && parseFloat(words[first + 2], p.z);
}

bool isDegenerate(const std::array<std::uint32_t, 3>& t) {
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

// Splits a polygon into the triangles (p0, pi, pi+1). Triangles that repeat a vertex have no
// area and would make a closed mesh look open, so they are left out.
void addFan(const std::vector<std::uint32_t>& polygon, TriangleMesh& mesh) {
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const std::array<std::uint32_t, 3> t{polygon[0], polygon[i], polygon[i + 1]};
    if (!isDegenerate(t)) mesh.triangles.push_back(t);
  }
}

// ---- Wavefront OBJ ----

// An index into the vertices as written in a face, before it is checked against the total.
struct FaceCorner {
  long long written;       // as in the file: 1-based, or negative counting from the end
  std::uint32_t resolved;  // 0-based
};

FaceCorner parseFaceCorner(const fs::path& file, const LineReader& reader, std::string_view word,
                           std::size_t faceNumber, std::size_t verticesSoFar) {
  // Only the vertex index matters: "a", "a/b", "a/b/c" and "a//c" all start with it.
  const std::string_view index = word.substr(0, word.find('/'));
  long long value = 0;
  const auto [end, error] = std::from_chars(index.data(), index.data() + index.size(), value);
  if (error != std::errc() || end != index.data() + index.size() || value == 0) {
    failAt(file, reader.number(),
           "expected vertex indices (1, 2, ... or -1, -2, ...) after 'f', got " + reader.quoted());
  }
  if (value > 0) return {value, static_cast<std::uint32_t>(value - 1)};
  const long long fromEnd = static_cast<long long>(verticesSoFar) + value;
  if (fromEnd < 0) {
    failAt(file, reader.number(),
           "face " + std::to_string(faceNumber) + " refers to vertex " + std::to_string(value) +
               " but only " + std::to_string(verticesSoFar) + " vertices precede it");
  }
  return {value, static_cast<std::uint32_t>(fromEnd)};
}

TriangleMesh readObj(const fs::path& file, std::string_view text) {
  TriangleMesh mesh;
  LineReader reader(text);
  std::vector<std::uint32_t> polygon;
  std::size_t faceNumber = 0;
  // Positive indices may point past the vertices read so far; they are checked at the end.
  struct PendingCheck {
    std::size_t line, face;
    long long written;
  };
  std::vector<PendingCheck> highest;
  while (reader.next()) {
    const auto& words = reader.words();
    if (words.empty()) continue;
    if (words[0] == "v") {
      Vec3 p{};
      // An optional fourth number (w) or three colour values may follow; they are not needed.
      bool valid = parsePoint(words, 1, p);
      for (std::size_t i = 4; valid && i < words.size(); ++i) {
        float extra = 0.0f;
        valid = parseFloat(words[i], extra);
      }
      if (!valid) {
        failAt(file, reader.number(), "expected 3 numbers after 'v', got " + reader.quoted());
      }
      mesh.vertices.push_back(p);
    } else if (words[0] == "f") {
      ++faceNumber;
      if (words.size() < 4) {
        failAt(file, reader.number(), "a face needs at least 3 vertices, got " + reader.quoted());
      }
      polygon.clear();
      PendingCheck check{reader.number(), faceNumber, 0};
      for (std::size_t i = 1; i < words.size(); ++i) {
        const FaceCorner corner =
            parseFaceCorner(file, reader, words[i], faceNumber, mesh.vertices.size());
        polygon.push_back(corner.resolved);
        check.written = std::max(check.written, corner.written);
      }
      if (check.written > static_cast<long long>(mesh.vertices.size())) highest.push_back(check);
      addFan(polygon, mesh);
    }
    // Everything else (vn, vt, o, g, s, usemtl, mtllib, l, ...) says nothing about the shape.
  }
  for (const PendingCheck& check : highest) {
    if (check.written > static_cast<long long>(mesh.vertices.size())) {
      failAt(file, check.line,
             "face " + std::to_string(check.face) + " refers to vertex " +
                 std::to_string(check.written) + " but the file has " +
                 std::to_string(mesh.vertices.size()) + " vertices");
    }
  }
  return mesh;
}

// ---- STL ----

// STL stores every triangle's corners separately; merging bit-identical corners recovers the
// connectivity that closedness and inside tests need.
class VertexWelder {
 public:
  explicit VertexWelder(TriangleMesh& mesh) : mesh_(mesh) {}

  std::uint32_t add(Vec3 p) {
    // + 0.0f turns -0 into +0 so that the two weld.
    const Key key{bits(p.x + 0.0f), bits(p.y + 0.0f), bits(p.z + 0.0f)};
    const auto [it, inserted] =
        index_.try_emplace(key, static_cast<std::uint32_t>(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  using Key = std::array<std::uint32_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ull;
      for (std::uint32_t v : k) h = (h ^ v) * 1099511628211ull;
      return static_cast<std::size_t>(h);
    }
  };
  static std::uint32_t bits(float v) {
    std::uint32_t b = 0;
    std::memcpy(&b, &v, sizeof b);
    return b;
  }

  TriangleMesh& mesh_;
  std::unordered_map<Key, std::uint32_t, KeyHash> index_;
};

constexpr std::size_t kBinaryHeaderBytes = 84;  // 80-byte header + uint32 triangle count
constexpr std::size_t kBinaryRecordBytes = 50;  // normal, 3 corners (12 floats) + uint16

// Binary STL is little-endian whatever the machine.
std::uint32_t readLittleEndian32(const std::string& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[offset + i]);
  return value;
}

float readLittleEndianFloat(const std::string& bytes, std::size_t offset) {
  const std::uint32_t b = readLittleEndian32(bytes, offset);
  float value = 0.0f;
  std::memcpy(&value, &b, sizeof value);
  return value;
}

TriangleMesh readBinaryStl(const fs::path& file, const std::string& bytes, std::uint32_t count) {
  TriangleMesh mesh;
  VertexWelder welder(mesh);
  for (std::uint32_t t = 0; t < count; ++t) {
    const std::size_t record = kBinaryHeaderBytes + kBinaryRecordBytes * t;
    std::array<std::uint32_t, 3> triangle{};
    for (int corner = 0; corner < 3; ++corner) {
      const std::size_t at = record + 12 + 12 * corner;  // after the facet normal
      const Vec3 p{readLittleEndianFloat(bytes, at), readLittleEndianFloat(bytes, at + 4),
                   readLittleEndianFloat(bytes, at + 8)};
      if (!isFinite(p)) {
        fail(file, "triangle " + std::to_string(t + 1) + " has a coordinate that is not finite");
      }
      triangle[corner] = welder.add(p);
    }
    if (!isDegenerate(triangle)) mesh.triangles.push_back(triangle);
  }
  return mesh;
}

bool hasBinaryBytes(std::string_view line) {
  return std::any_of(line.begin(), line.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u == 0 || (u < 32 && !std::isspace(u));
  });
}

TriangleMesh readAsciiStl(const fs::path& file, std::string_view text) {
  enum class Where { kOutside, kInSolid, kInFacet, kInLoop };
  static const char* const kExpected[] = {"'solid'", "'facet' or 'endsolid'",
                                          "'outer loop' or 'endfacet'", "'vertex' or 'endloop'"};
  TriangleMesh mesh;
  VertexWelder welder(mesh);
  LineReader reader(text);
  Where where = Where::kOutside;
  std::vector<std::uint32_t> loop;
  while (reader.next()) {
    const auto& words = reader.words();
    if (words.empty()) continue;
    const std::string_view keyword = words[0];
    if (std::any_of(words.begin(), words.end(), hasBinaryBytes)) {
      failAt(file, reader.number(),
             "binary data in an ASCII STL (a binary STL must be exactly 84 + 50 * count bytes)");
    }
    if (keyword == "solid" && where == Where::kOutside) {
      where = Where::kInSolid;
    } else if (keyword == "endsolid" && where == Where::kInSolid) {
      where = Where::kOutside;
    } else if (keyword == "facet" && where == Where::kInSolid) {
      where = Where::kInFacet;  // the stored normal is ignored: the winding defines the outside
    } else if (keyword == "outer" && where == Where::kInFacet && words.size() >= 2 &&
               words[1] == "loop") {
      where = Where::kInLoop;
      loop.clear();
    } else if (keyword == "vertex" && where == Where::kInLoop) {
      Vec3 p{};
      if (words.size() != 4 || !parsePoint(words, 1, p)) {
        failAt(file, reader.number(), "expected 3 numbers after 'vertex', got " + reader.quoted());
      }
      loop.push_back(welder.add(p));
    } else if (keyword == "endloop" && where == Where::kInLoop) {
      if (loop.size() < 3) {
        failAt(file, reader.number(),
               "a facet needs at least 3 vertices, got " + std::to_string(loop.size()));
      }
      addFan(loop, mesh);
      where = Where::kInFacet;
    } else if (keyword == "endfacet" && where == Where::kInFacet) {
      where = Where::kInSolid;
    } else {
      failAt(file, reader.number(),
             "expected " + std::string(kExpected[static_cast<int>(where)]) + ", got " +
                 reader.quoted());
    }
  }
  // A missing 'endsolid' is common and harmless; a cut-off facet is not.
  if (where == Where::kInFacet || where == Where::kInLoop) fail(file, "ends inside a facet");
  return mesh;
}

bool startsWithSolid(std::string_view bytes) {
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && bytes.substr(first, 5) == "solid";
}

TriangleMesh readStl(const fs::path& file, const std::string& bytes) {
  // Binary files often start with "solid" too, so the size decides first.
  std::uint32_t count = 0;
  if (bytes.size() >= kBinaryHeaderBytes) {
    count = readLittleEndian32(bytes, 80);
    if (kBinaryHeaderBytes + kBinaryRecordBytes * std::uint64_t{count} == bytes.size()) {
      return readBinaryStl(file, bytes, count);
    }
  }
  if (startsWithSolid(bytes)) return readAsciiStl(file, bytes);
  if (bytes.size() < kBinaryHeaderBytes) {
    fail(file, "not an STL file: no 'solid' at the start and only " + std::to_string(bytes.size()) +
                   " bytes, fewer than a binary STL header");
  }
  fail(file, "not an STL file: no 'solid' at the start, and as binary STL its header counts " +
                 std::to_string(count) + " triangles, which take " +
                 std::to_string(kBinaryHeaderBytes + kBinaryRecordBytes * std::uint64_t{count}) +
                 " bytes, but the file has " + std::to_string(bytes.size()));
}

std::string lowerCaseExtension(const fs::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// ".obj" or ".stl", lower case; anything else fails naming the file.
std::string requireMeshExtension(const fs::path& file) {
  const std::string extension = lowerCaseExtension(file);
  if (extension != ".obj" && extension != ".stl") {
    fail(file, "not an OBJ or STL file (" +
                   (extension.empty() ? std::string("no extension")
                                      : "extension " + file.extension().string()) +
                   ")");
  }
  return extension;
}

}  // namespace

TriangleMesh loadMesh(const fs::path& file) {
  requireMeshExtension(file);
  return parseMesh(readWholeFile(file), file);
}

TriangleMesh parseMesh(const std::string& bytes, const fs::path& file) {
  const std::string extension = requireMeshExtension(file);
  TriangleMesh mesh = extension == ".obj" ? readObj(file, bytes) : readStl(file, bytes);
  if (mesh.triangles.empty()) fail(file, "the mesh has no triangles");
  // A million metres is no scene's geometry; past it the samplers' lattice indices overflow.
  constexpr float kFarthest = 1e6f;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3 p = mesh.vertices[v];
    if (std::abs(p.x) > kFarthest || std::abs(p.y) > kFarthest || std::abs(p.z) > kFarthest)
      fail(file, "vertex " + std::to_string(v + 1) + " lies at (" + std::to_string(p.x) + ", " +
                     std::to_string(p.y) + ", " + std::to_string(p.z) +
                     "), farther than 1e6 from the origin on an axis");
  }
  return mesh;
}

}  // namespace sph::objects
