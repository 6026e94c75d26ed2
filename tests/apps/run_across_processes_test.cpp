// `mpirun -np N sph run`: the command line's run across processes, end to end. The step's
// agreement with one process bit for bit is tested in tests/distributed; here, what a user gets:
// one series of parallel frames holding every particle once, the statistics of all of them,
// summary.json's account of the division, and failures that end every process alike.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_sph.hpp"
#include "sph/io/frame_reader.hpp"

namespace fs = std::filesystem;

namespace {

using sph::testing::CommandResult;

// Under the sanitizers (a tenth of the speed) the runs are shorter.
#ifdef SPH_TESTS_SANITIZED
constexpr const char* kDuration = "0.01";
#else
constexpr const char* kDuration = "0.05";
#endif

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// mpirun -np `ranks` sph ARGUMENTS: 3 on 2 cores oversubscribed, as root where CI runs so.
CommandResult runAcross(int ranks, const std::string& arguments) {
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 1);
  setenv("OMPI_MCA_mpi_yield_when_idle", "1", 1);
  setenv("OMPI_MCA_mca_base_component_disable_dlclose", "1", 1);
#ifdef SPH_TESTS_SANITIZED
  // OpenMPI's own lasting allocations are named and suppressed; ours are still checked.
  const std::string suppressions =
      "suppressions=" + std::string(SPH_SOURCE_DIR) + "/tests/distributed/lsan_mpi.supp";
  setenv("LSAN_OPTIONS", suppressions.c_str(), 1);
  const char* asan = std::getenv("ASAN_OPTIONS");
  const std::string unwind =
      (asan != nullptr && *asan != '\0' ? std::string(asan) + ":" : "") + "fast_unwind_on_malloc=0";
  setenv("ASAN_OPTIONS", unwind.c_str(), 1);
#endif
  const fs::path log =
      fs::path(::testing::TempDir()) /
      ("sph_mpi_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
       ".log");
  const std::string command = std::string(SPH_MPIEXEC) + " -np " + std::to_string(ranks) + " " +
                              SPH_BINARY + " " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(log)};
}

class RunAcrossProcesses : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::path(::testing::TempDir()) /
        ("sph_mpi_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    scene_ = dir_ / "dam.json";
    // A column of 15 × 15 × 7 particles collapsing in its tank.
    std::ofstream(scene_) << R"({
      "name": "dam",
      "domain": {"min": [-0.05, -0.05, -0.05], "max": [1.05, 0.8, 0.15]},
      "fluid": {"spacing": 0.0133333, "viscosity": {"model": "artificial", "value": 0.02},
                "blocks": [{"min": [0, 0, 0], "max": [0.2, 0.2, 0.1]}]},
      "walls": [{"type": "tank", "min": [0, 0, 0], "max": [1.0, 0.4, 0.1], "layers": 2}],
      "time": {"duration": 0.05},
      "output": {"fps": 100}
    })";
  }
  std::string run(const fs::path& out, const std::string& extra = "") const {
    return "run " + scene_.string() + " --out " + out.string() +
           " --threads 1 --quiet --duration " + kDuration + " " + extra;
  }
  fs::path dir_, scene_;
};

TEST_F(RunAcrossProcesses, WritesOneSeriesOfParallelFramesHoldingEveryParticleOnce) {
  for (int ranks : {2, 3}) {
    const fs::path out = dir_ / ("ranks" + std::to_string(ranks));
    const CommandResult r = runAcross(ranks, run(out));
    ASSERT_EQ(r.code, 0) << r.output;
    const nlohmann::json summary = nlohmann::json::parse(readFile(out / "summary.json"));
    EXPECT_EQ(summary["status"], "completed");
    EXPECT_EQ(summary["distributed"]["ranks"], ranks);
    EXPECT_GT(summary["distributed"]["mean_ghost_share"].get<double>(), 0.0);
    const std::uint64_t n = summary["final"]["fluid_count"];
    ASSERT_GT(n, 1000u);
    const std::string series = readFile(out / "frames.pvd");
    EXPECT_NE(series.find("frames/frame_00000.pvtp"), std::string::npos) << series;
    const int frames = summary["frames"];
    ASSERT_GE(frames, 2);
    char last[64];
    std::snprintf(last, sizeof last, "frame_%05d.pvtp", frames - 1);
    const sph::ParticleFrame f = sph::io::readFrame(out / "frames" / last);
    ASSERT_EQ(f.size(), n);
    for (std::size_t i = 0; i < f.size(); ++i) ASSERT_EQ(f.id[i], i) << "of " << f.size();
    for (int r = 0; r < ranks; ++r)
      EXPECT_TRUE(fs::exists(out / "frames" / ("frame_00000_" + std::to_string(r) + ".vtp")));
    // The statistics are every process's: the count of the whole fluid in every row.
    std::istringstream rows(readFile(out / "stats.csv"));
    std::string line;
    std::getline(rows, line);
    int counted = 0;
    while (std::getline(rows, line)) {
      std::vector<std::string> cells;
      std::stringstream cellsOf(line);
      for (std::string cell; std::getline(cellsOf, cell, ',');) cells.push_back(cell);
      ASSERT_GT(cells.size(), 3u);
      EXPECT_EQ(std::stoull(cells[3]), n) << line;
      ++counted;
    }
    EXPECT_EQ(counted, frames);
  }
}

TEST_F(RunAcrossProcesses, AFailureEndsEveryProcessWithTheRunsCodeAndKeepsTheFrames) {
  const fs::path out = dir_ / "blowup";
  const CommandResult r = runAcross(2, run(out, "--set failure.max_density_error=0.002"));
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("simulation failed at step"), std::string::npos) << r.output;
  const nlohmann::json summary = nlohmann::json::parse(readFile(out / "summary.json"));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000.pvtp"));
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000_1.vtp"));
}

TEST_F(RunAcrossProcesses, SaysOnceWhatIsNotYetRunAcrossProcesses) {
  const CommandResult r = runAcross(2, run(dir_ / "pbf", "--set fluid.solver=pbf"));
  EXPECT_EQ(r.code, 2) << r.output;
  const std::string said = "not yet run across processes";
  const std::size_t first = r.output.find(said);
  ASSERT_NE(first, std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(said, first + 1), std::string::npos) << r.output;
}

}  // namespace
