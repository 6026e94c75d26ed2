// sph view under a virtual display (Xvfb): the window opens, runs a few frames and writes a
// screenshot in which the fluid is drawn. Skipped, with the reason, where xvfb-run is missing.
#include <gtest/gtest.h>
#include <png.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // top row first
  const std::uint8_t* at(int x, int y) const { return &rgb[3 * (std::size_t(y) * width + x)]; }
};

Image readPng(const fs::path& file) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  Image out;
  if (!png_image_begin_read_from_file(&image, file.c_str())) return out;
  image.format = PNG_FORMAT_RGB;
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr)) return {};
  out.width = int(image.width);
  out.height = int(image.height);
  return out;
}

TEST(ViewCli, OpensUnderXvfbRunsAndWritesAScreenshotShowingTheFluid) {
  if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "xvfb-run is not installed (Debian: xvfb), so no display for the viewer";
  const fs::path dir = fs::path(::testing::TempDir()) / "sph_view_cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = dir / "block.json";
  // A block of fluid on the floor of a tank, against a kinematic paddle whose force the panel
  // plots; the camera frames the domain.
  std::ofstream(scene) << R"({
    "name": "block",
    "domain": {"min": [0, 0, 0], "max": [0.1, 0.1, 0.1]},
    "fluid": {"spacing": 0.005, "blocks": [{"min": [0, 0, 0], "max": [0.1, 0.04, 0.1]}]},
    "walls": [{"type": "tank", "min": [0, 0, 0], "max": [0.1, 0.1, 0.1]}],
    "time": {"duration": 1.0},
    "objects": [{"name": "paddle", "motion": "kinematic",
                 "shape": {"type": "box", "center": [0.07, 0.03, 0.05],
                           "half_extents": [0.004, 0.015, 0.03]}}],
    "probes": [{"name": "floor", "type": "point", "position": [0.05, 0.01, 0.05]},
               {"name": "gauge", "type": "level", "from": [0.05, 0, 0.05], "to": [0.05, 0.1, 0.05]}]
  })";
  const fs::path shot = dir / "view.png";
  const fs::path log = dir / "view.log";
  // Under the sanitizers the viewer's process keeps ASan's and UBSan's checks but not the leak
  // check: at exit GLX unloads Mesa's driver before LeakSanitizer reports, so the driver's
  // lasting allocations come from an unknown module that no suppression can name.
  const std::string command =
      "ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\" "
      "xvfb-run -a -s '-screen 0 800x600x24' " +
      std::string(SPH_BINARY) + " view " + scene.string() +
      " --no-probe --frames 5 --width 800 --height 600 --screenshot " + shot.string() + " > " +
      log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::stringstream output;
  output << std::ifstream(log).rdbuf();
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << output.str();

  const Image image = readPng(shot);
  ASSERT_EQ(image.width, 800) << output.str();
  ASSERT_EQ(image.height, 600);
  // Right of the panel: the fluid's blue (0.2, 0.5, 0.9 before shading) covers a good part of
  // the view; an empty, black or panel-only image has none.
  std::size_t blue = 0, lit = 0, total = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 400; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      ++total;
      if (p[0] + p[1] + p[2] > 3 * 60) ++lit;
      if (p[2] > p[0] + 60 && p[2] > p[1] + 20) ++blue;
    }
  EXPECT_GT(blue, total / 20) << "blue " << blue << " of " << total;
  EXPECT_GT(lit, total / 20);
}

}  // namespace
