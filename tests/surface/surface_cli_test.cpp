// sph surface and sph run --surface on a tiny run: a mesh per frame in the format asked for, a
// ParaView series of them, exit 2 for a directory that is not a run's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../apps/run_sph.hpp"

namespace fs = std::filesystem;

namespace {

using Result = sph::testing::CommandResult;

class SurfaceCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("sph_surface_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    scene_ = dir_ / "drop.json";
    // Three frames (t = 0, 0.01, 0.02) of a small block in a walled tank.
    std::ofstream(scene_) << R"({
      "name": "drop",
      "domain": {"min": [0, 0, 0], "max": [0.1, 0.1, 0.1]},
      "fluid": {"spacing": 0.01, "blocks": [{"min": [0.0, 0.0, 0.0], "max": [0.05, 0.05, 0.05]}]},
      "walls": [{"type": "tank", "min": [0, 0, 0], "max": [0.1, 0.1, 0.1]}],
      "time": {"duration": 0.02},
      "output": {"fps": 100}
    })";
  }
  Result runSph(const std::string& arguments) {
    return sph::testing::runSph(arguments, "sph_surface_");
  }
  fs::path dir_, scene_;
};

TEST_F(SurfaceCli, RunWithSurfaceWritesAMeshPerFrameAndTheirSeries) {
  const fs::path out = dir_ / "out";
  const Result r = runSph("run " + scene_.string() + " --out " + out.string() + " --surface");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("surfaces:"), std::string::npos) << r.output;
  for (const char* name : {"frame_00000.vtp", "frame_00001.vtp", "frame_00002.vtp"})
    EXPECT_TRUE(fs::exists(out / "surface" / name)) << name;
  std::ifstream pvd(out / "surface.pvd");
  const std::string series((std::istreambuf_iterator<char>(pvd)), std::istreambuf_iterator<char>());
  EXPECT_NE(series.find("file=\"surface/frame_00002.vtp\""), std::string::npos) << series;

  // Again as PLY: the VTP meshes of the earlier call are gone.
  const Result ply = runSph("surface " + out.string() + " --format ply --quiet");
  ASSERT_EQ(ply.code, 0) << ply.output;
  EXPECT_TRUE(fs::exists(out / "surface" / "frame_00002.ply"));
  EXPECT_FALSE(fs::exists(out / "surface" / "frame_00002.vtp"));
}

TEST_F(SurfaceCli, ADirectoryThatIsNotARunsExitsTwoNamingWhatIsMissing) {
  const Result none = runSph("surface " + (dir_ / "nothing").string());
  EXPECT_EQ(none.code, 2) << none.output;
  // Frames without the run's summary: no spacing to size the level set with.
  const fs::path out = dir_ / "out";
  ASSERT_EQ(runSph("run " + scene_.string() + " --out " + out.string() + " --quiet").code, 0);
  fs::remove(out / "summary.json");
  const Result r = runSph("surface " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("summary.json"), std::string::npos) << r.output;
  EXPECT_EQ(runSph("surface " + out.string() + " --voxel 0").code, 2);
}

}  // namespace
