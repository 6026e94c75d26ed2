#include "sph/io/pvd_series.hpp"

#include "io/pvd_reader.hpp"
#include "sph/error.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sph::io {
namespace {

namespace fs = std::filesystem;

class PvdSeriesTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() / ("sph_pvd_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// (timestep, file) of every DataSet, in document order. Plain string search rather than
// std::regex, which GCC 12 warns inside at -O1 and above.
std::vector<std::pair<double, std::string>> dataSets(const std::string& pvd) {
  const auto attribute = [](const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const std::size_t found = tag.find(key);
    if (found == std::string::npos) return std::string();
    const std::size_t start = found + key.size();
    return tag.substr(start, tag.find('"', start) - start);
  };
  std::vector<std::pair<double, std::string>> sets;
  for (std::size_t at = pvd.find("<DataSet "); at != std::string::npos;
       at = pvd.find("<DataSet ", at + 1)) {
    const std::string tag = pvd.substr(at, pvd.find("/>", at) + 2 - at);
    sets.emplace_back(std::stod(attribute(tag, "timestep")), attribute(tag, "file"));
  }
  return sets;
}

bool isCompleteCollection(const std::string& pvd) {
  const std::string tail = "  </Collection>\n</VTKFile>\n";
  return pvd.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\"", 0) == 0 &&
         pvd.find("<Collection>") != std::string::npos && pvd.size() >= tail.size() &&
         pvd.compare(pvd.size() - tail.size(), tail.size(), tail) == 0;
}

TEST_F(PvdSeriesTest, ListsEveryFrameInOrderAfterEachAdd) {
  const fs::path pvd = dir_ / "run.pvd";
  PvdSeries series(pvd);
  EXPECT_FALSE(fs::exists(pvd));

  series.add(0.0, "frames/frame_00000.vtp");
  std::string text = readAll(pvd);
  EXPECT_TRUE(isCompleteCollection(text)) << text;
  EXPECT_EQ(dataSets(text),
            (std::vector<std::pair<double, std::string>>{{0.0, "frames/frame_00000.vtp"}}));

  series.add(1.0 / 30.0, "frames/frame_00001.vtp");
  series.add(0.1, "frames/frame_00002.vtp");
  text = readAll(pvd);
  EXPECT_TRUE(isCompleteCollection(text)) << text;
  EXPECT_EQ(dataSets(text),
            (std::vector<std::pair<double, std::string>>{{0.0, "frames/frame_00000.vtp"},
                                                         {1.0 / 30.0, "frames/frame_00001.vtp"},
                                                         {0.1, "frames/frame_00002.vtp"}}));
  EXPECT_NE(text.find("timestep=\"0.1\""), std::string::npos) << "times should read naturally";
  EXPECT_FALSE(fs::exists(dir_ / "run.pvd.tmp"));
}

TEST_F(PvdSeriesTest, FileNamesAreEscapedForXml) {
  const fs::path pvd = dir_ / "run.pvd";
  PvdSeries series(pvd);
  series.add(0.5, "a&b\"c.vtp");
  EXPECT_EQ(dataSets(readAll(pvd)),
            (std::vector<std::pair<double, std::string>>{{0.5, "a&amp;b&quot;c.vtp"}}));
}

TEST_F(PvdSeriesTest, ReadsBackWhatItWrites) {
  const fs::path pvd = dir_ / "run.pvd";
  PvdSeries series(pvd);
  series.add(0.0, "frames/frame_00000.vtp");
  series.add(1.0 / 30.0, "frames/a&b.vtp");
  EXPECT_EQ(readPvd(readAll(pvd), pvd),
            (std::vector<std::pair<double, std::string>>{{0.0, "frames/frame_00000.vtp"},
                                                         {1.0 / 30.0, "frames/a&b.vtp"}}));
}

// What a damaged or hostile collection holds is refused naming the file and what was wrong.
TEST(PvdReader, RefusesWhatIsNotACollectionOfFramesBesideIt) {
  const auto error = [](const std::string& bytes) {
    try {
      readPvd(bytes, "run/frames.pvd");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string head = "<VTKFile type=\"Collection\"><Collection>";
  EXPECT_EQ(error(head + "<DataSet timestep='0.5' file='frames/f.vtp'/>"), "accepted");
  EXPECT_NE(error("").find("run/frames.pvd: not a VTK collection"), std::string::npos);
  EXPECT_NE(error(head).find("lists no DataSet"), std::string::npos);
  EXPECT_NE(error(head + "<DataSet timestep=\"0\" file=\"f.vtp\"").find("not closed"),
            std::string::npos);
  EXPECT_NE(error(head + "<DataSet file=\"f.vtp\"/>").find("DataSet 1: expected a timestep"),
            std::string::npos);
  EXPECT_NE(error(head + "<DataSet timestep=\"soon\" file=\"f.vtp\"/>").find("not a number"),
            std::string::npos);
  EXPECT_NE(error(head + "<DataSet timestep=\"1e999\" file=\"f.vtp\"/>").find("not a number"),
            std::string::npos);
  for (const char* outside : {"/etc/passwd", "../other/f.vtp", "frames/../../f.vtp", ""})
    EXPECT_NE(error(head + "<DataSet timestep=\"0\" file=\"" + outside + "\"/>")
                  .find("not a file inside the collection's folder"),
              std::string::npos)
        << outside;
  // An unknown entity is not guessed at.
  EXPECT_NE(error(head + "<DataSet timestep=\"0\" file=\"a&nbsp;b.vtp\"/>").find("file"),
            std::string::npos);
}

TEST_F(PvdSeriesTest, MissingDirectoryThrowsNamingThePath) {
  const fs::path pvd = dir_ / "no_such_dir" / "run.pvd";
  PvdSeries series(pvd);
  try {
    series.add(0.0, "frame.vtp");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(pvd.string()), std::string::npos) << error.what();
  }
  // The failed frame is forgotten, so a later successful add lists it once.
  fs::create_directories(pvd.parent_path());
  series.add(0.0, "frame.vtp");
  EXPECT_EQ(dataSets(readAll(pvd)).size(), 1u);
}

}  // namespace
}  // namespace sph::io
