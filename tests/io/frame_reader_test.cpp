// Frames written by writeFrame read back identical in every format; damaged files and run
// directories give errors that name the file.
#include "sph/io/frame_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sph/error.hpp"
#include "sph/io/frame_writer.hpp"

namespace sph::io {
namespace {

namespace fs = std::filesystem;

class FrameReaderTest : public testing::TestWithParam<FrameFormat> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("sph_frame_reader_" + std::to_string(::getpid()) + "_" +
            std::to_string(testing::UnitTest::GetInstance()->random_seed()) + "_" +
            std::to_string(counter_++));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path fileFor(FrameFormat format, const std::string& stem = "frame") const {
    return dir_ / (stem + "." + frameExtension(format));
  }
  fs::path dir_;
  static inline int counter_ = 0;
};

ParticleFrame makeFrame() {
  ParticleFrame f;
  f.time = 0.1;
  f.step = 42;
  f.id = {3, 0, 4000000000u, 17, 5};
  for (std::size_t i = 0; i < f.id.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      // 0.1f and 1/3 need every digit to come back bit-identical through the CSV.
      f.position.push_back(0.1f + static_cast<float>(i) + static_cast<float>(c) / 3.0f);
      f.velocity.push_back(-1.5f * static_cast<float>(i) + 0.3f * static_cast<float>(c));
    }
    f.density.push_back(1000.0f + 0.7f * static_cast<float>(i));
    f.pressure.push_back(-20.0f + 3.3f * static_cast<float>(i));
    f.kind.push_back(static_cast<std::uint8_t>(i % 3));
    f.object.push_back(i % 3 == 2 ? static_cast<std::int32_t>(i) : -1);
    f.surface.push_back(static_cast<std::uint8_t>(i == 1 ? 1 : 0));
    f.torn.push_back(static_cast<std::uint8_t>(i == 2 ? 1 : 0));
  }
  return f;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeAll(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST_P(FrameReaderTest, RoundTripsEveryField) {
  const ParticleFrame written = makeFrame();
  const fs::path file = fileFor(GetParam());
  writeFrame(written, GetParam(), file);
  const ParticleFrame read = readFrame(file);
  EXPECT_EQ(read.id, written.id);
  EXPECT_EQ(read.position, written.position);
  EXPECT_EQ(read.velocity, written.velocity);
  EXPECT_EQ(read.density, written.density);
  EXPECT_EQ(read.pressure, written.pressure);
  EXPECT_EQ(read.kind, written.kind);
  EXPECT_EQ(read.object, written.object);
  EXPECT_EQ(read.surface, written.surface);
  // Tears go into VTP alone; the others read back none.
  if (GetParam() == FrameFormat::Vtp)
    EXPECT_EQ(read.torn, written.torn);
  else
    EXPECT_TRUE(read.torn.empty());
  if (GetParam() != FrameFormat::Csv) {  // CSV holds no time
    EXPECT_DOUBLE_EQ(read.time, 0.1);
  }
  if (GetParam() == FrameFormat::Ply) {
    EXPECT_EQ(read.step, 42u);
  }
}

TEST_P(FrameReaderTest, ReadsAnEmptyFrame) {
  const fs::path file = fileFor(GetParam());
  writeFrame(ParticleFrame{}, GetParam(), file);
  EXPECT_EQ(readFrame(file).size(), 0u);
}

TEST_P(FrameReaderTest, TruncatedFileNamesTheFile) {
  const fs::path file = fileFor(GetParam());
  writeFrame(makeFrame(), GetParam(), file);
  const std::string bytes = readAll(file);
  // Cut inside the data: the VTP's appended arrays, the PLY's vertices, the CSV's last row.
  writeAll(file, bytes.substr(0, bytes.size() - 60));
  try {
    readFrame(file);
    FAIL() << "a truncated " << frameExtension(GetParam()) << " file was read without error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

TEST_P(FrameReaderTest, GarbageNamesTheFileAndWhatWasExpected) {
  const fs::path file = fileFor(GetParam());
  writeAll(file, "this is not a frame\n1,2,3\n");
  try {
    readFrame(file);
    FAIL() << "garbage was read as a frame";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    EXPECT_GT(message.size(), file.string().size() + 10) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(AllFormats, FrameReaderTest,
                         testing::Values(FrameFormat::Vtp, FrameFormat::Ply, FrameFormat::Csv),
                         [](const testing::TestParamInfo<FrameFormat>& info) {
                           return std::string(frameExtension(info.param));
                         });

class RunFramesTest : public FrameReaderTest {};

TEST_F(RunFramesTest, ListsFramesInNumberOrderWithTheBoundary) {
  fs::create_directories(dir_ / "frames");
  for (const char* name : {"frame_00010.ply", "frame_00002.ply", "frame_00000.ply"})
    writeFrame(makeFrame(), FrameFormat::Ply, dir_ / "frames" / name);
  writeAll(dir_ / "frames" / "frame_00011.ply.tmp", "a frame being written");
  // 20 digits once ended the listing with "error: stol".
  writeAll(dir_ / "frames" / "frame_12345678901234567890.ply", "no run writes this");
  writeFrame(makeFrame(), FrameFormat::Ply, dir_ / "boundary.ply");
  const RunFrameFiles files = listRunFrames(dir_);
  ASSERT_EQ(files.frames.size(), 3u);
  EXPECT_EQ(files.frames[0].filename(), "frame_00000.ply");
  EXPECT_EQ(files.frames[1].filename(), "frame_00002.ply");
  EXPECT_EQ(files.frames[2].filename(), "frame_00010.ply");
  EXPECT_EQ(files.boundary, dir_ / "boundary.ply");
}

// A run's frames.pvd decides which frames there are, in its order, with their times: a stray
// frame file it does not list is left out, and one it lists that is gone is an error.
TEST_F(RunFramesTest, TheSeriesListsTheFramesAndTheirTimes) {
  fs::create_directories(dir_ / "frames");
  for (const char* name : {"frame_00000.vtp", "frame_00001.vtp", "frame_00007.vtp"})
    writeFrame(makeFrame(), FrameFormat::Vtp, dir_ / "frames" / name);
  writeAll(
      dir_ / "frames.pvd",
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
      "  <Collection>\n"
      "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"frames/frame_00000.vtp\"/>\n"
      "    <DataSet timestep=\"0.02\" group=\"\" part=\"0\" file=\"frames/frame_00001.vtp\"/>\n"
      "  </Collection>\n</VTKFile>\n");
  const RunFrameFiles files = listRunFrames(dir_);
  ASSERT_EQ(files.frames.size(), 2u);
  EXPECT_EQ(files.frames[1], dir_ / "frames" / "frame_00001.vtp");
  EXPECT_EQ(files.times, (std::vector<double>{0.0, 0.02}));

  fs::remove(dir_ / "frames" / "frame_00001.vtp");
  try {
    listRunFrames(dir_);
    FAIL() << "a listed frame that is gone was not noticed";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("frames.pvd: lists 'frames/frame_00001.vtp', which is missing"),
        std::string::npos)
        << e.what();
  }
  writeAll(dir_ / "frames.pvd",
           "<VTKFile type=\"Collection\"><DataSet timestep=\"x\" file=\"a.vtp\"/>");
  EXPECT_THROW(listRunFrames(dir_), InputError);
}

TEST_F(RunFramesTest, NoBoundaryWhenTheRunHasNoWalls) {
  fs::create_directories(dir_ / "frames");
  writeFrame(makeFrame(), FrameFormat::Vtp, dir_ / "frames" / "frame_00000.vtp");
  EXPECT_TRUE(listRunFrames(dir_).boundary.empty());
}

// /dev/zero once grew the reader's buffer until memory ran out.
TEST_F(RunFramesTest, ADeviceOrADirectoryIsNotAFrame) {
  if (fs::exists("/dev/zero")) {
    fs::create_directories(dir_ / "frames");
    fs::create_symlink("/dev/zero", dir_ / "frames" / "frame_00000.csv");
    try {
      readFrame(dir_ / "frames" / "frame_00000.csv");
      FAIL() << "read /dev/zero as a frame";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is not a regular file"), std::string::npos) << e.what();
    }
  }
  fs::create_directories(dir_ / "a.vtp");
  EXPECT_THROW(readFrame(dir_ / "a.vtp"), InputError);
}

// Found by fuzz_csv: a surface flag of 5.6e87 reached an integer cast (undefined behaviour).
TEST(CsvFrameReader, ValuesTheirColumnCannotHoldAreRefused) {
  const std::string header = "id,kind,object,x,y,z,vx,vy,vz,density,pressure,surface\n";
  const auto error = [&](const std::string& row) {
    try {
      readCsvFrame(header + row + "\n", "f.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error("0,0,-1,0,0,0,0,0,0,1000,0,1"), "accepted");
  EXPECT_NE(error("0,0,-1,0,0,0,0,0,0,1000,0,5.6e87").find("line 2, column 'surface'"),
            std::string::npos);
  EXPECT_NE(error("1e20,0,-1,0,0,0,0,0,0,1000,0,0").find("column 'id'"), std::string::npos);
  EXPECT_NE(error("0,0,-5e9,0,0,0,0,0,0,1000,0,0").find("column 'object'"), std::string::npos);
  EXPECT_NE(error("0,0,-1,1e300,0,0,0,0,0,1000,0,0").find("column 'x'"), std::string::npos);
  EXPECT_NE(error("0.5,0,-1,0,0,0,0,0,0,1000,0,0").find("is not an integer"), std::string::npos);
}

TEST_F(RunFramesTest, DirectoryWithoutFramesIsAnInputError) {
  EXPECT_THROW(listRunFrames(dir_ / "missing"), InputError);
  EXPECT_THROW(listRunFrames(dir_), InputError);  // no frames/ folder
  fs::create_directories(dir_ / "frames");
  try {
    listRunFrames(dir_);
    FAIL() << "an empty frames folder was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("frames"), std::string::npos) << e.what();
  }
}

TEST_F(RunFramesTest, MixedFormatsAreAnInputError) {
  fs::create_directories(dir_ / "frames");
  writeFrame(makeFrame(), FrameFormat::Vtp, dir_ / "frames" / "frame_00000.vtp");
  writeFrame(makeFrame(), FrameFormat::Csv, dir_ / "frames" / "frame_00001.csv");
  EXPECT_THROW(listRunFrames(dir_), InputError);
}

}  // namespace
}  // namespace sph::io
