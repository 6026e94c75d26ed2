// sph render and sph run --render on a tiny run: PNG images of the requested size, a video where
// ffmpeg exists, exit 2 for bad input. Skipped, with the reason, where no offscreen context can
// be made.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "../apps/run_sph.hpp"

namespace fs = std::filesystem;

namespace {

using Result = sph::testing::CommandResult;

Result runSph(const std::string& arguments) {
  return sph::testing::runSph(arguments, "sph_render_");
}

bool ffmpegOnPath() {
  return std::system("command -v ffmpeg > /dev/null 2>&1") == 0;
}

bool noOffscreenContext(const Result& r) {
  return r.code != 0 && r.output.find("rendering without a display needs EGL") != std::string::npos;
}

// Width and height from a PNG's IHDR chunk; {0, 0} when the file is not a PNG.
std::pair<int, int> pngSize(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!in || !std::equal(signature, signature + 8, header)) return {0, 0};
  auto big = [&](int at) {
    return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3];
  };
  return {big(16), big(20)};
}

class RenderCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("sph_render_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    scene_ = dir_ / "drop.json";
    // Three frames (t = 0, 0.01, 0.02) of a small block in a walled tank, with a box object.
    std::ofstream(scene_) << R"({
      "name": "drop",
      "domain": {"min": [0, 0, 0], "max": [0.1, 0.1, 0.1]},
      "fluid": {"spacing": 0.01, "blocks": [{"min": [0.0, 0.0, 0.0], "max": [0.05, 0.05, 0.05]}]},
      "walls": [{"type": "tank", "min": [0, 0, 0], "max": [0.1, 0.1, 0.1]}],
      "objects": [{"name": "cube", "motion": "kinematic",
                   "shape": {"type": "box", "center": [0.08, 0.03, 0.05],
                             "half_extents": [0.01, 0.01, 0.01]}}],
      "time": {"duration": 0.02},
      "output": {"fps": 100}
    })";
  }
  fs::path dir_, scene_;
};

TEST_F(RenderCli, RenderWritesImagesAndVideo) {
  const fs::path run = dir_ / "run";
  ASSERT_EQ(runSph("run " + scene_.string() + " --out " + run.string() + " --quiet").code, 0);
  // Odd sizes: the video pads them to even.
  const Result r = runSph("render " + run.string() + " --width 97 --height 61 --colour density");
  if (noOffscreenContext(r)) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.code, ffmpegOnPath() ? 0 : 4) << r.output;
  for (const char* name : {"frame_00000.png", "frame_00001.png", "frame_00002.png"})
    EXPECT_EQ(pngSize(run / "images" / name), std::make_pair(97, 61)) << name;
  EXPECT_FALSE(fs::exists(run / "images" / "frame_00003.png"));
  EXPECT_NE(r.output.find("kg/m3"), std::string::npos) << "the colour range is reported\n"
                                                       << r.output;
  if (!ffmpegOnPath()) {
    EXPECT_NE(r.output.find("ffmpeg"), std::string::npos) << r.output;
    GTEST_SKIP() << "ffmpeg is not on PATH: the images were checked, the video was not";
  }
  ASSERT_TRUE(fs::exists(run / "video.mp4")) << r.output;
  EXPECT_GT(fs::file_size(run / "video.mp4"), 500u);
  EXPECT_NE(r.output.find("video.mp4"), std::string::npos) << r.output;
}

TEST_F(RenderCli, RunWithRenderEndsWithImages) {
  const fs::path run = dir_ / "run";
  const Result r = runSph("run " + scene_.string() + " --out " + run.string() +
                          " --format ply --quiet --render");
  if (noOffscreenContext(r)) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.code, ffmpegOnPath() ? 0 : 4) << r.output;
  EXPECT_EQ(pngSize(run / "images" / "frame_00002.png"), std::make_pair(1280, 720));
  EXPECT_TRUE(fs::exists(run / "frames" / "frame_00002.ply"));
  if (ffmpegOnPath()) {
    EXPECT_TRUE(fs::exists(run / "video.mp4"));
  }
}

// An encoder that fails leaves the images and says so, exiting 4 like any result that could
// not be written.
TEST_F(RenderCli, AFailingVideoEncoderExitsFourKeepingTheImages) {
  const fs::path run = dir_ / "run";
  ASSERT_EQ(runSph("run " + scene_.string() + " --out " + run.string() + " --quiet").code, 0);
  const fs::path fakeBin = dir_ / "bin";
  fs::create_directories(fakeBin);
  std::ofstream(fakeBin / "ffmpeg") << "#!/bin/sh\necho 'disk full' >&2\nexit 1\n";
  fs::permissions(fakeBin / "ffmpeg", fs::perms::owner_all);
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", (fakeBin.string() + ":" + path).c_str(), 1);
  const Result r = runSph("render " + run.string() + " --width 32 --height 32 --quiet");
  setenv("PATH", path.c_str(), 1);
  if (noOffscreenContext(r)) GTEST_SKIP() << r.output;
  EXPECT_EQ(r.code, 4) << r.output;
  EXPECT_NE(r.output.find("no video: ffmpeg failed"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(run / "images" / "frame_00002.png"));
  EXPECT_FALSE(fs::exists(run / "video.mp4"));
}

TEST_F(RenderCli, ShowsWallsAndGridWithoutVideo) {
  const fs::path run = dir_ / "run";
  ASSERT_EQ(runSph("run " + scene_.string() + " --out " + run.string() + " --quiet").code, 0);
  const Result r = runSph("render " + run.string() +
                          " --width 64 --height 48 --boundary --grid --no-video --colour speed "
                          "--range 0,1 --quiet");
  if (noOffscreenContext(r)) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(pngSize(run / "images" / "frame_00000.png"), std::make_pair(64, 48));
  EXPECT_FALSE(fs::exists(run / "video.mp4"));
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The run writes its objects' surfaces once; the renderer draws the cube as its surface unless
// asked for particles, and a damaged surfaces file is bad input naming it.
TEST_F(RenderCli, ObjectsAreDrawnAsTheirSurfaces) {
  const fs::path run = dir_ / "run";
  ASSERT_EQ(runSph("run " + scene_.string() + " --out " + run.string() + " --quiet").code, 0);
  ASSERT_TRUE(fs::exists(run / "object_surfaces.vtp"));
  Result r = runSph("render " + run.string() + " --width 64 --height 48 --no-video --quiet");
  if (noOffscreenContext(r)) GTEST_SKIP() << r.output;
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string surface = readAll(run / "images" / "frame_00002.png");
  r = runSph("render " + run.string() +
             " --width 64 --height 48 --no-video --quiet --objects particles");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(readAll(run / "images" / "frame_00002.png"), surface);
  EXPECT_EQ(runSph("render " + run.string() + " --objects cubes").code, 2);

  std::ofstream(run / "object_surfaces.vtp", std::ios::trunc) << "<?xml version";
  r = runSph("render " + run.string() + " --no-video --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("object_surfaces.vtp"), std::string::npos) << r.output;
  // Particles need no surfaces.
  EXPECT_EQ(runSph("render " + run.string() + " --no-video --quiet --objects particles").code, 0);
}

TEST_F(RenderCli, BadInputExitsTwoNamingIt) {
  Result r = runSph("render " + (dir_ / "nowhere").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("nowhere"), std::string::npos) << r.output;

  fs::create_directories(dir_ / "empty" / "frames");
  r = runSph("render " + (dir_ / "empty").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("frames"), std::string::npos) << r.output;

  const fs::path run = dir_ / "run";
  ASSERT_EQ(runSph("run " + scene_.string() + " --out " + run.string() + " --quiet").code, 0);
  EXPECT_EQ(runSph("render " + run.string() + " --colour temperature").code, 2);
  EXPECT_EQ(runSph("render " + run.string() + " --range 1").code, 2);
  std::ofstream(run / "summary.json") << "{ not json";
  r = runSph("render " + run.string() + " --no-video");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("summary.json"), std::string::npos) << r.output;
}

}  // namespace
