// Writes small frames through writeFrame and reads them back the way a VTK XML reader does: the
// header's offsets into the raw appended block, each block prefixed by its UInt64 byte count.
#include "io/vtp_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "sph/io/frame_writer.hpp"

namespace sph::io {
namespace {

namespace fs = std::filesystem;

class VtpWriterTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() / ("sph_vtp_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

ParticleFrame makeFrame() {
  ParticleFrame f;
  f.time = 0.1;
  f.step = 42;
  f.id = {3, 0, 4000000000u, 17};
  for (std::size_t i = 0; i < f.id.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      f.position.push_back(0.1f + static_cast<float>(i) + 0.25f * static_cast<float>(c));
      f.velocity.push_back(-1.5f * static_cast<float>(i) + 0.3f * static_cast<float>(c));
    }
    f.density.push_back(1000.0f + 0.7f * static_cast<float>(i));
    f.pressure.push_back(-20.0f + 3.3f * static_cast<float>(i));
    f.kind.push_back(static_cast<std::uint8_t>(i % 2));
    f.object.push_back(i == 3 ? 2 : -1);
    f.surface.push_back(static_cast<std::uint8_t>(i == 1 ? 1 : 0));
  }
  return f;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct ArrayInfo {
  std::string type;
  int components = 1;
  std::string bytes;  // the block's payload, after its UInt64 count
};

struct ParsedVtp {
  std::uint64_t points = 0;
  std::uint64_t verts = 0;
  std::string time;
  std::map<std::string, ArrayInfo> arrays;
  std::string trailer;  // what follows the last block
};

// std::regex is avoided: GCC 12 warns inside <regex> at -O1 and above (-Wmaybe-uninitialized).
std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t start = tag.find(key);
  if (start == std::string::npos) return "";
  const std::size_t valueStart = start + key.size();
  return tag.substr(valueStart, tag.find('"', valueStart) - valueStart);
}

// Every `<name ...>` tag in `text`, in document order.
std::vector<std::string> tags(const std::string& text, const std::string& name) {
  std::vector<std::string> found;
  for (std::size_t at = text.find("<" + name + " "); at != std::string::npos;
       at = text.find("<" + name + " ", at + 1)) {
    found.push_back(text.substr(at, text.find('>', at) + 1 - at));
  }
  return found;
}

ParsedVtp parseVtp(const std::string& content) {
  ParsedVtp vtp;
  const std::string marker = "<AppendedData encoding=\"raw\">";
  const std::size_t appended = content.find(marker);
  if (appended == std::string::npos) throw std::runtime_error("no AppendedData");
  const std::string header = content.substr(0, appended);
  const std::size_t base = content.find('_', appended + marker.size()) + 1;

  const std::vector<std::string> pieces = tags(header, "Piece");
  if (pieces.size() != 1) throw std::runtime_error("expected one Piece");
  vtp.points = std::stoull(attribute(pieces[0], "NumberOfPoints"));
  vtp.verts = std::stoull(attribute(pieces[0], "NumberOfVerts"));

  std::size_t end = base;
  for (const std::string& tag : tags(header, "DataArray")) {
    if (attribute(tag, "Name") == "TIME") {
      const std::size_t valueStart = header.find(tag) + tag.size();
      vtp.time = header.substr(valueStart, header.find('<', valueStart) - valueStart);
      continue;
    }
    if (attribute(tag, "format") != "appended") throw std::runtime_error("not appended: " + tag);
    ArrayInfo info;
    info.type = attribute(tag, "type");
    const std::string components = attribute(tag, "NumberOfComponents");
    if (!components.empty()) info.components = std::stoi(components);
    const std::size_t at = base + std::stoull(attribute(tag, "offset"));
    std::uint64_t count = 0;
    std::memcpy(&count, content.data() + at, sizeof count);
    info.bytes = content.substr(at + sizeof count, count);
    end = std::max<std::size_t>(end, at + sizeof count + count);
    vtp.arrays[attribute(tag, "Name")] = info;
  }
  vtp.trailer = content.substr(end);
  return vtp;
}

template <typename T>
std::vector<T> values(const ArrayInfo& array) {
  std::vector<T> out(array.bytes.size() / sizeof(T));
  std::memcpy(out.data(), array.bytes.data(), out.size() * sizeof(T));
  return out;
}

TEST_F(VtpWriterTest, EveryArrayReadsBackAsWritten) {
  const ParticleFrame frame = makeFrame();
  const fs::path file = dir_ / "frame.vtp";
  writeFrame(frame, FrameFormat::Vtp, file);
  const std::string content = readAll(file);

  EXPECT_EQ(content.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
                          "byte_order=\"LittleEndian\" header_type=\"UInt64\">",
                          0),
            0u);
  const ParsedVtp vtp = parseVtp(content);
  EXPECT_EQ(vtp.points, 4u);
  EXPECT_EQ(vtp.verts, 4u);
  EXPECT_EQ(vtp.time, "0.1");
  ASSERT_EQ(vtp.arrays.size(), 10u);
  EXPECT_EQ(vtp.trailer, "\n  </AppendedData>\n</VTKFile>\n");

  const auto& arrays = vtp.arrays;
  EXPECT_EQ(arrays.at("Points").type, "Float32");
  EXPECT_EQ(arrays.at("Points").components, 3);
  EXPECT_EQ(values<float>(arrays.at("Points")), frame.position);
  EXPECT_EQ(arrays.at("velocity").components, 3);
  EXPECT_EQ(values<float>(arrays.at("velocity")), frame.velocity);
  EXPECT_EQ(arrays.at("density").type, "Float32");
  EXPECT_EQ(values<float>(arrays.at("density")), frame.density);
  EXPECT_EQ(values<float>(arrays.at("pressure")), frame.pressure);
  EXPECT_EQ(arrays.at("kind").type, "UInt8");
  EXPECT_EQ(values<std::uint8_t>(arrays.at("kind")), frame.kind);
  EXPECT_EQ(arrays.at("object").type, "Int32");
  EXPECT_EQ(values<std::int32_t>(arrays.at("object")), frame.object);
  EXPECT_EQ(arrays.at("surface").type, "UInt8");
  EXPECT_EQ(values<std::uint8_t>(arrays.at("surface")), frame.surface);
  EXPECT_EQ(arrays.at("id").type, "UInt32");
  EXPECT_EQ(values<std::uint32_t>(arrays.at("id")), frame.id);
  EXPECT_EQ(arrays.at("connectivity").type, "Int64");
  EXPECT_EQ(values<std::int64_t>(arrays.at("connectivity")),
            (std::vector<std::int64_t>{0, 1, 2, 3}));
  EXPECT_EQ(values<std::int64_t>(arrays.at("offsets")), (std::vector<std::int64_t>{1, 2, 3, 4}));
}

TEST_F(VtpWriterTest, EmptyFrameIsValid) {
  ParticleFrame frame;
  const fs::path file = dir_ / "empty.vtp";
  writeFrame(frame, FrameFormat::Vtp, file);
  const ParsedVtp vtp = parseVtp(readAll(file));
  EXPECT_EQ(vtp.points, 0u);
  EXPECT_EQ(vtp.verts, 0u);
  ASSERT_EQ(vtp.arrays.size(), 10u);
  for (const auto& [name, array] : vtp.arrays) EXPECT_TRUE(array.bytes.empty()) << name;
  EXPECT_EQ(vtp.trailer, "\n  </AppendedData>\n</VTKFile>\n");
}

TEST_F(VtpWriterTest, ReplacesAnOlderFileAndLeavesNoTemporary) {
  const fs::path file = dir_ / "frame.vtp";
  std::ofstream(file) << "stale";
  writeFrame(makeFrame(), FrameFormat::Vtp, file);
  EXPECT_EQ(parseVtp(readAll(file)).points, 4u);
  EXPECT_FALSE(fs::exists(dir_ / "frame.vtp.tmp"));
}

TEST_F(VtpWriterTest, MissingDirectoryThrowsNamingThePath) {
  const fs::path file = dir_ / "no_such_dir" / "frame.vtp";
  try {
    writeFrame(makeFrame(), FrameFormat::Vtp, file);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(std::strerror(ENOENT)), std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(fs::exists(file));
}

TEST_F(VtpWriterTest, InconsistentFrameIsRejectedBeforeWriting) {
  ParticleFrame frame = makeFrame();
  frame.density.pop_back();
  const fs::path file = dir_ / "frame.vtp";
  EXPECT_THROW(writeFrame(frame, FrameFormat::Vtp, file), std::invalid_argument);
  EXPECT_FALSE(fs::exists(file));
}

TEST(FrameWriterTest, FormatDoubleIsShortestExact) {
  EXPECT_EQ(formatDouble(0.1), "0.1");
  EXPECT_EQ(formatDouble(2.5), "2.5");
  for (double value : {1.0 / 3.0, 0.1 + 0.2, 1e-300, -123456.789012345678}) {
    EXPECT_EQ(std::stod(formatDouble(value)), value) << formatDouble(value);
  }
}

TEST(FrameWriterTest, ExtensionsAndNoneFormat) {
  EXPECT_STREQ(frameExtension(FrameFormat::Vtp), "vtp");
  EXPECT_STREQ(frameExtension(FrameFormat::Ply), "ply");
  EXPECT_STREQ(frameExtension(FrameFormat::Csv), "csv");
  EXPECT_STREQ(frameExtension(FrameFormat::None), "");
  const fs::path file = fs::temp_directory_path() / "sph_none_format_never_written";
  writeFrame(makeFrame(), FrameFormat::None, file);
  EXPECT_FALSE(fs::exists(file));
}

}  // namespace
}  // namespace sph::io
