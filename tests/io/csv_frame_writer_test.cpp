#include "io/csv_frame_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sph/io/frame_writer.hpp"

namespace sph::io {
namespace {

namespace fs = std::filesystem;

class CsvFrameWriterTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() / ("sph_csv_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

ParticleFrame makeFrame() {
  ParticleFrame f;
  f.time = 0.5;
  f.id = {4, 2, 4000000000u, 0, 11};
  for (std::size_t i = 0; i < f.id.size(); ++i) {
    // Values like 0.1f and 1/3 need all nine digits to come back bit-identical.
    for (int c = 0; c < 3; ++c) {
      f.position.push_back(0.1f * static_cast<float>(i) + static_cast<float>(c) / 3.0f);
      f.velocity.push_back(-1e-7f * static_cast<float>(i + 1) + 12345.678f * static_cast<float>(c));
    }
    f.density.push_back(1000.0f / 3.0f + static_cast<float>(i));
    f.pressure.push_back(-0.1f * static_cast<float>(i) + 3e6f);
    f.kind.push_back(static_cast<std::uint8_t>(i % 2));
    f.object.push_back(i == 4 ? 3 : -1);
    f.surface.push_back(static_cast<std::uint8_t>(i % 3 == 0 ? 1 : 0));
  }
  return f;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

std::vector<std::string> readLines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST_F(CsvFrameWriterTest, RowsRoundTripExactly) {
  const ParticleFrame frame = makeFrame();
  const fs::path file = dir_ / "frame.csv";
  writeFrame(frame, FrameFormat::Csv, file);
  const std::vector<std::string> lines = readLines(file);

  ASSERT_EQ(lines.size(), 1 + frame.size());
  EXPECT_EQ(lines[0], "id,kind,object,x,y,z,vx,vy,vz,density,pressure,surface");
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const std::vector<std::string> f = split(lines[1 + i]);
    ASSERT_EQ(f.size(), 12u) << lines[1 + i];
    EXPECT_EQ(std::stoul(f[0]), frame.id[i]);
    EXPECT_EQ(std::stoi(f[1]), frame.kind[i]);
    EXPECT_EQ(std::stoi(f[2]), frame.object[i]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(std::strtof(f[3 + c].c_str(), nullptr), frame.position[3 * i + c]);
      EXPECT_EQ(std::strtof(f[6 + c].c_str(), nullptr), frame.velocity[3 * i + c]);
    }
    EXPECT_EQ(std::strtof(f[9].c_str(), nullptr), frame.density[i]);
    EXPECT_EQ(std::strtof(f[10].c_str(), nullptr), frame.pressure[i]);
    EXPECT_EQ(std::stoi(f[11]), frame.surface[i]);
  }
}

TEST_F(CsvFrameWriterTest, EmptyFrameHasHeaderOnly) {
  const fs::path file = dir_ / "empty.csv";
  writeFrame(ParticleFrame{}, FrameFormat::Csv, file);
  EXPECT_EQ(readLines(file),
            std::vector<std::string>{"id,kind,object,x,y,z,vx,vy,vz,density,pressure,surface"});
}

TEST_F(CsvFrameWriterTest, MissingDirectoryThrowsNamingThePath) {
  const fs::path file = dir_ / "no_such_dir" / "frame.csv";
  try {
    writeFrame(makeFrame(), FrameFormat::Csv, file);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sph::io
