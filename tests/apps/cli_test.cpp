// The command-line contract (README.md): outputs, exit codes, and never overwriting a run.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "run_sph.hpp"

namespace fs = std::filesystem;

namespace {

using Result = sph::testing::CommandResult;

Result runSph(const std::string& arguments) {
  return sph::testing::runSph(arguments, "sph_cli_");
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::path(::testing::TempDir()) /
        ("sph_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    scene_ = dir_ / "drop.json";
    std::ofstream(scene_) << R"({
      "name": "drop",
      "domain": {"min": [0, 0, 0], "max": [0.1, 0.1, 0.1], "damped_box": true},
      "fluid": {"spacing": 0.01, "blocks": [{"min": [0.02, 0.04, 0.02], "max": [0.08, 0.08, 0.08]}]},
      "time": {"duration": 0.02},
      "output": {"fps": 100}
    })";
  }
  fs::path dir_, scene_;
};

TEST_F(Cli, RunWritesFramesStatsAndSummary) {
  const fs::path out = dir_ / "run";
  const Result r = runSph("run " + scene_.string() + " --out " + out.string() + " --quiet");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000.vtp"));
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_00002.vtp"));
  EXPECT_FALSE(fs::exists(out / "frames" / "frame_00003.vtp"));
  EXPECT_NE(readFile(out / "frames.pvd").find("frames/frame_00002.vtp"), std::string::npos);
  // A header and one row per frame: t = 0, 0.01, 0.02.
  const std::string stats = readFile(out / "stats.csv");
  EXPECT_EQ(std::count(stats.begin(), stats.end(), '\n'), 4);
  EXPECT_EQ(stats.rfind("time,steps,dt,", 0), 0u);
  const auto summary = nlohmann::json::parse(readFile(out / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_DOUBLE_EQ(summary["simulated_time"].get<double>(), 0.02);
  EXPECT_EQ(summary["calibration"]["fluid_particles"], 6 * 4 * 6);
  EXPECT_EQ(summary["scene"]["fluid"]["spacing"], 0.01);
}

TEST_F(Cli, RunWritesTheProbesAtTheirRate) {
  const fs::path scene = dir_ / "probed.json";
  std::ofstream(scene) << R"({
    "name": "probed",
    "domain": {"min": [0, 0, 0], "max": [0.1, 0.1, 0.1], "damped_box": true},
    "fluid": {"spacing": 0.01, "blocks": [{"min": [0.02, 0.0, 0.02], "max": [0.08, 0.06, 0.08]}]},
    "time": {"duration": 0.02},
    "output": {"fps": 100, "format": "none", "probe_rate": 500},
    "probes": [{"name": "p", "type": "point", "position": [0.05, 0.03, 0.05]},
               {"name": "g", "type": "level", "from": [0.05, 0, 0.05], "to": [0.05, 0.1, 0.05]}]
  })";
  const fs::path out = dir_ / "run";
  const Result r = runSph("run " + scene.string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("probes at 500 per second in"), std::string::npos) << r.output;
  // A header and a row every 2 ms from 0 to 0.02 s.
  const std::string probes = readFile(out / "probes.csv");
  EXPECT_EQ(std::count(probes.begin(), probes.end(), '\n'), 12);
  EXPECT_EQ(probes.rfind("time_s,p_pressure_Pa,p_density_kg_m3,p_vx_m_s,p_vy_m_s,p_vz_m_s,"
                         "g_level_m\n0,",
                         0),
            0u)
      << probes;
  EXPECT_NE(probes.find("\n0.02,"), std::string::npos) << probes;

  // sph plot draws both files.
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  const Result plot = runSph("plot " + out.string());
  ASSERT_EQ(plot.code, 0) << plot.output;
  for (const char* png : {"stats.png", "probes.png"}) {
    const std::string image = readFile(out / "plots" / png);
    EXPECT_EQ(image.rfind("\x89PNG", 0), 0u) << png;
  }
  EXPECT_EQ(runSph("plot " + (dir_ / "nothing").string()).code, 2);
}

TEST_F(Cli, FormatsAndOverridesFromTheCommandLine) {
  const fs::path out = dir_ / "ply";
  const Result r = runSph("run " + scene_.string() + " --out " + out.string() +
                          " --quiet --format ply --fps 50 --set time.duration=0.04");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_00002.ply"));
  EXPECT_FALSE(fs::exists(out / "frames" / "frame_00003.ply"));
  EXPECT_EQ(readFile(out / "frames" / "frame_00000.ply").rfind("ply\n", 0), 0u);
}

TEST_F(Cli, NeverOverwritesAnEarlierRunUnlessForced) {
  const fs::path out = dir_ / "run";
  ASSERT_EQ(runSph("run " + scene_.string() + " --out " + out.string() + " --quiet").code, 0);
  const std::string before = readFile(out / "stats.csv");
  const Result again = runSph("run " + scene_.string() + " --out " + out.string() +
                              " --quiet --set time.duration=0.01");
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.output.find("--force"), std::string::npos) << again.output;
  EXPECT_EQ(readFile(out / "stats.csv"), before) << "the earlier run must be untouched";
  // What a run killed while writing its summary (kill -9) left: --force clears it too, and
  // leaves what is not a run's.
  std::ofstream(out / "summary.json.tmp") << "{\"stat";
  std::ofstream(out / "notes.txt") << "mine";
  const Result forced = runSph("run " + scene_.string() + " --out " + out.string() +
                               " --quiet --force --set time.duration=0.01");
  EXPECT_EQ(forced.code, 0) << forced.output;
  EXPECT_NE(readFile(out / "stats.csv"), before);
  EXPECT_FALSE(fs::exists(out / "summary.json.tmp"));
  EXPECT_EQ(readFile(out / "notes.txt"), "mine");
  // A directory holding only such a temporary holds an earlier run.
  const fs::path killed = dir_ / "killed";
  fs::create_directories(killed);
  std::ofstream(killed / "frames.pvd.tmp") << "<?xml";
  EXPECT_EQ(runSph("run " + scene_.string() + " --out " + killed.string() + " --quiet").code, 2);
}

TEST_F(Cli, BadInputExitsTwoNamingFileAndKey) {
  const Result r = runSph("run " + scene_.string() + " --out " + (dir_ / "bad").string() +
                          " --set fluid.spacng=0.02");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("drop.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("fluid.spacng"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("fluid.spacing"), std::string::npos) << "suggests the nearest key";
  EXPECT_FALSE(fs::exists(dir_ / "bad" / "stats.csv"));

  EXPECT_EQ(runSph("run " + (dir_ / "missing.json").string()).code, 2);
  EXPECT_EQ(runSph("run " + scene_.string() + " --backend cuda").code, 2);
  EXPECT_EQ(runSph("validate " + scene_.string() + " --set fluid.spacing=-1").code, 2);
  // Too large for the machine: refused at once with the count, not a bad_alloc minutes later.
  const Result huge = runSph("run " + scene_.string() + " --out " + (dir_ / "huge").string() +
                             " --set fluid.spacing=0.000001");
  EXPECT_EQ(huge.code, 2);
  EXPECT_NE(huge.output.find("drop.json: fluid.spacing: the scene would make"), std::string::npos)
      << huge.output;
  EXPECT_FALSE(fs::exists(dir_ / "huge" / "stats.csv"));
  // 100,000 threads once crashed inside OpenMP.
  const Result threads = runSph("run " + scene_.string() + " --out " + (dir_ / "threads").string() +
                                " --threads 100000");
  EXPECT_EQ(threads.code, 2);
  EXPECT_NE(threads.output.find("--threads"), std::string::npos) << threads.output;
  EXPECT_NE(threads.output.find("1024"), std::string::npos) << threads.output;
}

// A scene far larger than the machine is refused before anything large is made: the process
// stays small (its own peak resident memory, from wait4), where building it would take
// terabytes.
TEST_F(Cli, AnOverLargeSceneExitsTwoBeforeAllocating) {
  for (const char* verb : {"validate", "run"}) {
    const std::string command =
        std::string(SPH_BINARY) + " " + verb + " " + scene_.string() +
        " --set fluid.spacing=0.000002 " +
        (std::string(verb) == "run" ? "--out " + (dir_ / "huge").string() : std::string()) +
        " > /dev/null 2>&1";
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    int status = 0;
    rusage usage{};
    ASSERT_EQ(wait4(child, &status, 0, &usage), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2) << verb;
    EXPECT_LT(usage.ru_maxrss, 200 * 1024) << verb << ": peak resident memory in kB";
  }
  EXPECT_FALSE(fs::exists(dir_ / "huge" / "stats.csv"));
}

// Results that cannot be written are neither bad input nor a failed simulation.
TEST_F(Cli, AnOutputDirectoryThatCannotBeMadeExitsFour) {
  const Result r = runSph("run " + scene_.string() + " --out /dev/null/run");
  EXPECT_EQ(r.code, 4) << r.output;
  EXPECT_NE(r.output.find("cannot create the output directory '/dev/null/run/frames'"),
            std::string::npos)
      << r.output;
}

TEST_F(Cli, BlowUpExitsThreeKeepingWhatWasComputed) {
  const fs::path out = dir_ / "blowup";
  const Result r = runSph(
      "run " + scene_.string() + " --out " + out.string() +
      " --quiet --set time.fixed_dt=0.005 --set calibration.stiffness=1e5 --set time.duration=0.5");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("particle"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("step"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000.vtp"));
  const auto summary = nlohmann::json::parse(readFile(out / "summary.json"));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_TRUE(summary["failure"].contains("particle"));
  const std::string stats = readFile(out / "stats.csv");
  EXPECT_GE(std::count(stats.begin(), stats.end(), '\n'), 2) << "header and the first frame";
}

TEST_F(Cli, ValidateAndInfo) {
  const Result v = runSph("validate " + scene_.string());
  EXPECT_EQ(v.code, 0) << v.output;
  EXPECT_NE(v.output.find("speed of sound"), std::string::npos);
  EXPECT_NE(v.output.find("derived"), std::string::npos);
  const Result i = runSph("info");
  EXPECT_EQ(i.code, 0);
  EXPECT_NE(i.output.find("cpu"), std::string::npos);
}

}  // namespace
