// Writes small frames through writeFrame and reads them back as a PLY reader would: the ASCII
// header names the properties in order, then each vertex's values follow, packed.
#include "io/ply_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sph/io/frame_writer.hpp"

namespace sph::io {
namespace {

namespace fs = std::filesystem;

class PlyWriterTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() / ("sph_ply_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

ParticleFrame makeFrame() {
  ParticleFrame f;
  f.time = 2.5;
  f.step = 7;
  f.id = {9, 1, 4000000000u};
  for (std::size_t i = 0; i < f.id.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      f.position.push_back(0.1f * static_cast<float>(i + 1) - 0.5f * static_cast<float>(c));
      f.velocity.push_back(3.0f - static_cast<float>(i) + 0.01f * static_cast<float>(c));
    }
    f.density.push_back(998.2f + static_cast<float>(i));
    f.pressure.push_back(101.5f * static_cast<float>(i) - 7.0f);
    f.kind.push_back(static_cast<std::uint8_t>(i == 1 ? 1 : 0));
    f.object.push_back(i == 2 ? 5 : -1);
    f.surface.push_back(static_cast<std::uint8_t>(i == 0 ? 1 : 0));
  }
  return f;
}

struct ParsedPly {
  std::vector<std::string> headerLines;
  std::string body;
};

ParsedPly readPly(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream all;
  all << in.rdbuf();
  const std::string content = all.str();
  const std::string end = "end_header\n";
  const std::size_t bodyStart = content.find(end) + end.size();
  ParsedPly ply;
  std::istringstream header(content.substr(0, bodyStart));
  for (std::string line; std::getline(header, line);) ply.headerLines.push_back(line);
  ply.body = content.substr(bodyStart);
  return ply;
}

template <typename T>
T take(const std::string& body, std::size_t& at) {
  T value;
  std::memcpy(&value, body.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

const std::vector<std::string> kExpectedProperties = {"property float x",
                                                      "property float y",
                                                      "property float z",
                                                      "property float vx",
                                                      "property float vy",
                                                      "property float vz",
                                                      "property float density",
                                                      "property float pressure",
                                                      "property uchar kind",
                                                      "property int object",
                                                      "property uchar surface",
                                                      "property uint id",
                                                      "end_header"};

TEST_F(PlyWriterTest, HeaderAndEveryVertexReadBack) {
  const ParticleFrame frame = makeFrame();
  const fs::path file = dir_ / "frame.ply";
  writeFrame(frame, FrameFormat::Ply, file);
  const ParsedPly ply = readPly(file);

  ASSERT_GE(ply.headerLines.size(), 3u);
  EXPECT_EQ(ply.headerLines[0], "ply");
  EXPECT_EQ(ply.headerLines[1], "format binary_little_endian 1.0");
  std::size_t line = 2;
  bool sawTime = false;
  for (; line < ply.headerLines.size() && ply.headerLines[line].rfind("comment", 0) == 0; ++line) {
    if (ply.headerLines[line] == "comment time 2.5") sawTime = true;
  }
  EXPECT_TRUE(sawTime);
  ASSERT_LT(line, ply.headerLines.size());
  EXPECT_EQ(ply.headerLines[line], "element vertex 3");
  const std::vector<std::string> properties(ply.headerLines.begin() + line + 1,
                                            ply.headerLines.end());
  EXPECT_EQ(properties, kExpectedProperties);

  constexpr std::size_t kVertexBytes = 8 * 4 + 1 + 4 + 1 + 4;
  ASSERT_EQ(ply.body.size(), frame.size() * kVertexBytes);
  std::size_t at = 0;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(take<float>(ply.body, at), frame.position[3 * i + c]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(take<float>(ply.body, at), frame.velocity[3 * i + c]);
    EXPECT_EQ(take<float>(ply.body, at), frame.density[i]);
    EXPECT_EQ(take<float>(ply.body, at), frame.pressure[i]);
    EXPECT_EQ(take<std::uint8_t>(ply.body, at), frame.kind[i]);
    EXPECT_EQ(take<std::int32_t>(ply.body, at), frame.object[i]);
    EXPECT_EQ(take<std::uint8_t>(ply.body, at), frame.surface[i]);
    EXPECT_EQ(take<std::uint32_t>(ply.body, at), frame.id[i]);
  }
}

TEST_F(PlyWriterTest, EmptyFrameHasHeaderOnly) {
  const fs::path file = dir_ / "empty.ply";
  writeFrame(ParticleFrame{}, FrameFormat::Ply, file);
  const ParsedPly ply = readPly(file);
  bool sawElement = false;
  for (const std::string& headerLine : ply.headerLines) {
    if (headerLine == "element vertex 0") sawElement = true;
  }
  EXPECT_TRUE(sawElement);
  ASSERT_FALSE(ply.headerLines.empty());
  EXPECT_EQ(ply.headerLines.back(), "end_header");
  EXPECT_TRUE(ply.body.empty());
}

TEST_F(PlyWriterTest, MissingDirectoryThrowsNamingThePath) {
  const fs::path file = dir_ / "no_such_dir" / "frame.ply";
  try {
    writeFrame(makeFrame(), FrameFormat::Ply, file);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sph::io
