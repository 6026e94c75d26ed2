// A distributed run's parallel frames (.pvtp over one VTP piece a process) read back as one
// frame in id order; damaged ones name what is wrong.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/pvtp_reader.hpp"
#include "sph/error.hpp"
#include "sph/io/frame_reader.hpp"
#include "sph/io/frame_writer.hpp"

namespace sph::io {
namespace {

namespace fs = std::filesystem;

ParticleFrame frameOf(std::uint32_t first, std::uint32_t step, std::uint32_t count) {
  ParticleFrame f;
  f.time = 0.25;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t id = first + k * step;
    f.id.push_back(id);
    f.position.insert(f.position.end(), {0.1f * float(id), 1.0f, -2.0f});
    f.velocity.insert(f.velocity.end(), {0.0f, -float(id), 0.5f});
    f.density.push_back(1000.0f + float(id));
    f.pressure.push_back(float(id));
    f.kind.push_back(id % 3 == 2 ? 2 : 0);
    f.object.push_back(id % 3 == 2 ? 0 : -1);
    f.surface.push_back(id % 2);
    f.torn.push_back(id % 5 == 0);
  }
  return f;
}

class Pvtp : public testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() / ("sph_pvtp_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// Two ranks' pieces, each in id order, their ids interleaved (even on one, odd on the other).
TEST_F(Pvtp, PiecesJoinIntoOneFrameInIdOrder) {
  writeFrame(frameOf(0, 2, 50), FrameFormat::Vtp, dir_ / "frame_00003_0.vtp");
  writeFrame(frameOf(1, 2, 50), FrameFormat::Vtp, dir_ / "frame_00003_1.vtp");
  writeParallelFrame({"frame_00003_0.vtp", "frame_00003_1.vtp"}, true, dir_ / "frame_00003.pvtp");
  const ParticleFrame joined = readFrame(dir_ / "frame_00003.pvtp");
  const ParticleFrame whole = frameOf(0, 1, 100);
  EXPECT_EQ(joined.id, whole.id);
  EXPECT_EQ(joined.position, whole.position);
  EXPECT_EQ(joined.velocity, whole.velocity);
  EXPECT_EQ(joined.density, whole.density);
  EXPECT_EQ(joined.pressure, whole.pressure);
  EXPECT_EQ(joined.kind, whole.kind);
  EXPECT_EQ(joined.object, whole.object);
  EXPECT_EQ(joined.surface, whole.surface);
  EXPECT_EQ(joined.torn, whole.torn);
  EXPECT_DOUBLE_EQ(joined.time, 0.25);
}

// A series of parallel frames: the run's walls are one VTP beside them.
TEST_F(Pvtp, ARunOfParallelFramesListsThemAndItsWalls) {
  writeFrame(frameOf(0, 1, 10), FrameFormat::Vtp, dir_ / "frame_00000_0.vtp");
  writeParallelFrame({"frame_00000_0.vtp"}, true, dir_ / "frame_00000.pvtp");
  writeFrame(frameOf(100, 1, 10), FrameFormat::Vtp, dir_ / "boundary.vtp");
  std::ofstream(dir_ / "frames.pvd") << R"(<?xml version="1.0"?>
<VTKFile type="Collection" version="0.1"><Collection>
<DataSet timestep="0" file="frame_00000.pvtp"/>
</Collection></VTKFile>
)";
  const RunFrameFiles files = listRunFrames(dir_);
  ASSERT_EQ(files.frames.size(), 1u);
  EXPECT_EQ(files.frames[0], dir_ / "frame_00000.pvtp");
  EXPECT_EQ(files.boundary, dir_ / "boundary.vtp");
}

void expectError(const fs::path& file, const std::string& what) {
  try {
    readFrame(file);
    FAIL() << "read without error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST_F(Pvtp, DamagedFramesSayWhatIsWrong) {
  writeFrame(frameOf(0, 1, 10), FrameFormat::Vtp, dir_ / "a.vtp");
  writeFrame(frameOf(5, 1, 10), FrameFormat::Vtp, dir_ / "b.vtp");
  writeParallelFrame({"a.vtp", "b.vtp"}, true, dir_ / "overlap.pvtp");
  expectError(dir_ / "overlap.pvtp", "two pieces hold particle 5");
  writeParallelFrame({"a.vtp", "missing.vtp"}, true, dir_ / "missing.pvtp");
  expectError(dir_ / "missing.pvtp", "missing.vtp");
  writeParallelFrame({"../a.vtp"}, true, dir_ / "outside.pvtp");
  expectError(dir_ / "outside.pvtp", "not a .vtp file inside the frame's folder");
  std::ofstream(dir_ / "empty.pvtp") << "<VTKFile type=\"PPolyData\"></VTKFile>";
  expectError(dir_ / "empty.pvtp", "lists no Piece");
  std::ofstream(dir_ / "other.pvtp") << "ply\n";
  expectError(dir_ / "other.pvtp", "not a parallel VTK PolyData file");
}

}  // namespace
}  // namespace sph::io
