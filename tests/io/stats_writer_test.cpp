#include "sph/io/stats_writer.hpp"
#include "sph/error.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sph::io {
namespace {

namespace fs = std::filesystem;

class StatsWriterTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() / ("sph_stats_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

const char* const kHeader =
    "time,steps,dt,fluid_count,boundary_count,kinetic_energy,mean_density,max_density_error,"
    "max_speed,surface_count,leaked_count,removed_count,wall_ms_per_step,contact_pairs,"
    "average_density_error,density_iterations_per_step,divergence_iterations_per_step,"
    "unconverged_solves,emitted_count,clamped_count";

std::vector<std::string> readLines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

FrameStats makeStats(int row) {
  FrameStats s;
  s.time = 0.25 * row;
  s.steps = 100u * static_cast<unsigned>(row) + 1;
  s.dt = 1.5e-4;
  s.fluidCount = 8000;
  s.boundaryCount = 1234;
  s.kineticEnergy = 0.5 + row;
  s.meanDensity = 1000.125;
  s.maxDensityError = 0.0125;
  s.maxSpeed = 2.75;
  s.surfaceCount = 300;
  s.leakedCount = static_cast<std::uint64_t>(row);
  s.removedCount = 12345678901234ull;
  s.wallMsPerStep = 3.5;
  s.contactPairs = 77;
  s.averageDensityError = 0.0005;
  // The solver's totals so far: 3 and 1 iterations a step.
  s.densityIterations = 3u * s.steps;
  s.divergenceIterations = s.steps;
  s.unconvergedSolves = 2;
  s.clampedCount = 5u * static_cast<std::uint64_t>(row);
  return s;
}

TEST_F(StatsWriterTest, HeaderThenOneFlushedRowPerAppend) {
  const fs::path file = dir_ / "stats.csv";
  StatsWriter writer(file);
  EXPECT_EQ(readLines(file), std::vector<std::string>{kHeader});

  writer.append(makeStats(1));
  writer.append(makeStats(2));
  // Read while the writer is still open: rows must already be on disk.
  const std::vector<std::string> lines = readLines(file);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], kHeader);
  EXPECT_EQ(lines[1],
            "0.25,101,0.00015,8000,1234,1.5,1000.125,0.0125,2.75,300,1,12345678901234,3.5,77,"
            "0.0005,3,1,2,0,5");
  const std::vector<std::string> fields = split(lines[2]);
  ASSERT_EQ(fields.size(), 20u);
  EXPECT_EQ(std::stod(fields[0]), 0.5);
  EXPECT_EQ(std::stoull(fields[1]), 201u);
  EXPECT_EQ(std::stod(fields[5]), 2.5);
  EXPECT_EQ(std::stoull(fields[10]), 2u);
  // Per step over the 100 steps since the last row.
  EXPECT_EQ(std::stod(fields[15]), 3.0);
  EXPECT_EQ(std::stod(fields[16]), 1.0);
  EXPECT_EQ(std::stoull(fields[19]), 10u);
}

TEST_F(StatsWriterTest, EachObjectHasForceAndCentreColumns) {
  const fs::path file = dir_ / "stats.csv";
  StatsWriter writer(file, {"box", "ball"});
  FrameStats s = makeStats(1);
  ObjectStats box;
  box.name = "box";
  box.fluidForce = {1.5, -2.0, 0.25};
  box.centreOfMass = {0.1, 0.2, 0.3};
  ObjectStats ball;
  ball.name = "ball";
  ball.fluidForce = {0, 9.75, 0};
  ball.centreOfMass = {-1, 0, 1};
  s.objects = {box, ball};
  writer.append(s);
  const std::vector<std::string> lines = readLines(file);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], std::string(kHeader) +
                          ",box_force_x,box_force_y,box_force_z,box_com_x,box_com_y,box_com_z"
                          ",ball_force_x,ball_force_y,ball_force_z,ball_com_x,ball_com_y,"
                          "ball_com_z");
  const std::vector<std::string> fields = split(lines[1]);
  ASSERT_EQ(fields.size(), 20u + 12u);
  EXPECT_EQ(std::stod(fields[20]), 1.5);
  EXPECT_EQ(std::stod(fields[22]), 0.25);
  EXPECT_EQ(std::stod(fields[25]), 0.3);
  EXPECT_EQ(std::stod(fields[27]), 9.75);
  EXPECT_EQ(std::stod(fields[29]), -1.0);
}

TEST_F(StatsWriterTest, NewWriterStartsAFreshFile) {
  const fs::path file = dir_ / "stats.csv";
  StatsWriter(file).append(makeStats(1));
  StatsWriter again(file);
  EXPECT_EQ(readLines(file), std::vector<std::string>{kHeader});
}

TEST_F(StatsWriterTest, MissingDirectoryThrowsNamingThePath) {
  const fs::path file = dir_ / "no_such_dir" / "stats.csv";
  try {
    StatsWriter writer(file);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
}

// /dev/full takes the open and refuses every write with ENOSPC: a full disk.
TEST_F(StatsWriterTest, AFullDiskIsAnOutputErrorNamingTheFileAndTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  try {
    StatsWriter writer("/dev/full");
    writer.append(makeStats(1));
    FAIL() << "a full disk took the rows";
  } catch (const OutputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("cannot write '/dev/full'"), std::string::npos) << message;
    EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  }
}

// A disk that fills up part-way through a row (here a file size limit, in a child process):
// the run is told, the row goes whole, and the rows before stay readable.
TEST_F(StatsWriterTest, ARowTheDiskTakesOnlyPartOfIsCutBackAndTheRowsBeforeStay) {
  const fs::path reference = dir_ / "reference.csv";
  { StatsWriter writer(reference); }
  const std::uintmax_t header = fs::file_size(reference);
  {
    StatsWriter writer(reference);
    writer.append(makeStats(1));
  }
  const std::uintmax_t row = fs::file_size(reference) - header;
  const fs::path file = dir_ / "stats.csv";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG
    const rlim_t limit = rlim_t(header + row + row / 2);
    const rlimit size{limit, limit};
    if (::setrlimit(RLIMIT_FSIZE, &size) != 0) ::_exit(2);
    try {
      StatsWriter writer(file);
      writer.append(makeStats(1));
      writer.append(makeStats(2));  // half of it fits
      ::_exit(3);
    } catch (const OutputError& error) {
      const std::string message = error.what();
      const bool named = message.find("cannot write '" + file.string() + "'") != std::string::npos;
      ::_exit(named && message.find("File too large") != std::string::npos ? 0 : 4);
    } catch (...) {
      ::_exit(5);
    }
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "2: no limit; 3: no error; 4: the message; 5: another error";
  EXPECT_EQ(fs::file_size(file), header + row);
  const std::vector<std::string> lines = readLines(file);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], kHeader);
  EXPECT_EQ(split(lines[1]).size(), 20u);
}

}  // namespace
}  // namespace sph::io
