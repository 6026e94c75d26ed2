// sph run --checkpoint-every / --resume: a run killed at a random moment and resumed from its
// newest checkpoint writes the same frames, probes and statistics as one never interrupted; a
// finished run extends with a longer --duration; a damaged checkpoint exits 2 naming it.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "run_sph.hpp"

namespace fs = std::filesystem;

namespace {

using Result = sph::testing::CommandResult;

// Under the sanitizers (a tenth of the speed) the runs are shorter: they check the same steps.
#ifdef SPH_TESTS_SANITIZED
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

Result runSph(const std::string& arguments) {
  return sph::testing::runSph(arguments, "sph_checkpoint_");
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// stats.csv without its wall_ms_per_step column, the one that times the machine.
std::string statsWithoutTimings(const fs::path& file) {
  std::istringstream in(readFile(file));
  std::string line, out;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    for (std::size_t k = 0; k < cells.size(); ++k)
      if (k != 12) out += cells[k] + ",";
    out += "\n";
  }
  return out;
}

class Checkpoints : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("sph_checkpoint_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  // The shipped pipe at a coarse spacing: walls, an emitter, an outlet and probes. Under the
  // sanitizers at 200 frames a second, so that their runs of a few hundredths of a second still
  // have frames and checkpoints to stop, kill and resume between.
  std::string pipe() const {
    return std::string(SPH_SOURCE_DIR) + "/scenes/pipe_flow.json --set fluid.spacing=0.01 --fps " +
           (kSanitized ? "200" : "50");
  }
  void expectSameRun(const fs::path& a, const fs::path& b) const {
    int frames = 0;
    for (const auto& entry : fs::directory_iterator(a / "frames")) {
      const fs::path other = b / "frames" / entry.path().filename();
      ASSERT_TRUE(fs::exists(other)) << other;
      EXPECT_EQ(readFile(entry.path()), readFile(other)) << entry.path().filename();
      ++frames;
    }
    EXPECT_EQ(frames,
              std::distance(fs::directory_iterator(b / "frames"), fs::directory_iterator{}));
    if (fs::exists(a / "probes.csv")) {
      EXPECT_EQ(readFile(a / "probes.csv"), readFile(b / "probes.csv"));
    }
    EXPECT_EQ(statsWithoutTimings(a / "stats.csv"), statsWithoutTimings(b / "stats.csv"));
    EXPECT_EQ(readFile(a / "frames.pvd"), readFile(b / "frames.pvd"));
  }
  void killAndResume(const std::string& scene, double every, int framesApart, int lastFrame);
  fs::path dir_;
};

// `scene` (with its options) run whole, and run again with checkpoints every `every` s and
// killed (SIGKILL) at a random moment after its first checkpoint, at frame `framesApart`;
// resumed, its outputs are those of the whole run, and it keeps the checkpoints at its last
// frame, `lastFrame`, and `framesApart` before.
void Checkpoints::killAndResume(const std::string& scene, double every, int framesApart,
                                int lastFrame) {
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  const Result reference = runSph("run " + scene + " --threads 2 --quiet --out " + whole.string());
  ASSERT_EQ(reference.code, 0) << reference.output;

  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string command = std::string(SPH_BINARY) + " run " + scene +
                                " --threads 1 --quiet --checkpoint-every " + std::to_string(every) +
                                " --out " + killed.string() + " > /dev/null 2>&1";
    execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  char first[64];
  std::snprintf(first, sizeof first, "checkpoint_%05d.sphck", framesApart);
  const auto start = std::chrono::steady_clock::now();
  while (!fs::exists(killed / "checkpoints" / first) &&
         std::chrono::steady_clock::now() - start < std::chrono::seconds(300))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  std::mt19937 random(std::random_device{}());
  std::this_thread::sleep_for(std::chrono::milliseconds(random() % 300));
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  const bool finished = WIFEXITED(status);
  EXPECT_EQ(fs::exists(killed / "summary.json"), finished) << "a killed run writes no summary";

  const Result resumed = runSph("run --resume " + killed.string() + " --threads 2 --quiet");
  if (finished) {  // a machine quick enough to finish first: nothing is left to run
    EXPECT_EQ(resumed.code, 2) << resumed.output;
    GTEST_SKIP() << "the run finished before it could be killed";
  }
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  expectSameRun(whole, killed);
  const auto summary = nlohmann::json::parse(readFile(killed / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_TRUE(summary["resumed_from"].contains("checkpoint"));
  // Checkpoints went on at the resumed run's interval, the last two kept, the last at the end.
  std::vector<std::string> kept;
  for (const auto& entry : fs::directory_iterator(killed / "checkpoints"))
    kept.push_back(entry.path().filename().string());
  std::sort(kept.begin(), kept.end());
  char last[2][64];
  std::snprintf(last[0], sizeof last[0], "checkpoint_%05d.sphck", lastFrame - framesApart);
  std::snprintf(last[1], sizeof last[1], "checkpoint_%05d.sphck", lastFrame);
  EXPECT_EQ(kept, (std::vector<std::string>{last[0], last[1]}));
}

// Walls, an emitter, an outlet and probes.
TEST_F(Checkpoints, AKilledRunResumesToTheSameBytes) {
  // Under the sanitizers past the emitter's first layer and the outlet's first drained (0.01 s).
  if (kSanitized)
    killAndResume(pipe() + " --duration 0.03", 0.01, 2, 6);
  else
    killAndResume(pipe() + " --duration 1.2", 0.1, 5, 60);
}

// The artery squeezed: a deformable vessel, the clamps, leak tracking, and the object engine in
// its own thread.
TEST_F(Checkpoints, AKilledRunWithObjectsResumesToTheSameBytes) {
  const std::string artery = std::string(SPH_SOURCE_DIR) + "/scenes/artery_squeeze.json --fps 100";
  // Under the sanitizers at half the fluid's resolution (a fifteenth of the time a step), past
  // the clamps' start at 0.05 s.
  if (kSanitized)
    killAndResume(artery + " --set fluid.spacing=0.002 --duration 0.08", 0.01, 1, 8);
  else
    killAndResume(artery + " --duration 0.12", 0.01, 1, 12);
}

TEST_F(Checkpoints, AFinishedRunExtendsWithALongerDuration) {
  const fs::path whole = dir_ / "whole", extended = dir_ / "extended";
  const std::string end = kSanitized ? "0.02" : "0.4", half = kSanitized ? "0.01" : "0.2";
  ASSERT_EQ(
      runSph("run " + pipe() + " --duration " + end + " --quiet --out " + whole.string()).code, 0);
  ASSERT_EQ(runSph("run " + pipe() + " --duration " + half + " --checkpoint-every " + half +
                   " --quiet --out " + extended.string())
                .code,
            0);
  const Result same = runSph("run --resume " + extended.string() + " --quiet");
  EXPECT_EQ(same.code, 2) << same.output;
  EXPECT_NE(same.output.find("time.duration"), std::string::npos) << same.output;
  const Result longer =
      runSph("run --resume " + extended.string() + " --duration " + end + " --quiet");
  ASSERT_EQ(longer.code, 0) << longer.output;
  expectSameRun(whole, extended);
}

// The dam break at 30 frames a second stopped at 0.05 s, between two frames, then extended to
// 0.1 s: the frames after the stop are those of a run never stopped. The stopped run's last
// step lands on 0.05 s, which the whole run steps past; its newest checkpoint is therefore of
// its last whole frame, from which the extension steps as the whole run did.
TEST_F(Checkpoints, ARunStoppedBetweenFramesExtendsToTheSameBytes) {
  // Under the sanitizers a coarser column: the same checks on an eighth of the particles.
  const std::string spacing = kSanitized ? "0.02" : "0.01";
  const std::string damBreak = std::string(SPH_SOURCE_DIR) +
                               "/scenes/dam_break.json --set fluid.spacing=" + spacing +
                               " --fps 30 --checkpoint-every 0.05 --threads 2 --quiet";
  const fs::path whole = dir_ / "whole", extended = dir_ / "extended";
  ASSERT_EQ(runSph("run " + damBreak + " --duration 0.1 --out " + whole.string()).code, 0);
  ASSERT_EQ(runSph("run " + damBreak + " --duration 0.05 --out " + extended.string()).code, 0);
  const Result same = runSph("run --resume " + extended.string() + " --quiet");
  EXPECT_EQ(same.code, 2) << same.output;
  EXPECT_NE(same.output.find("already reached t = 0.05 s"), std::string::npos) << same.output;
  const Result longer =
      runSph("run --resume " + extended.string() + " --duration 0.1 --threads 2 --quiet");
  ASSERT_EQ(longer.code, 0) << longer.output;
  expectSameRun(whole, extended);
}

TEST_F(Checkpoints, ADamagedCheckpointOrAMisusedResumeExitsTwoSayingWhy) {
  const fs::path run = dir_ / "run";
  // Under the sanitizers a quarter of the run, resumed to a fifth of the time: the newest
  // checkpoint is again of frame 5.
  const std::string duration = kSanitized ? "0.025" : "0.1", every = kSanitized ? "0.01" : "0.05";
  const std::string longer = kSanitized ? "0.04" : "0.2";
  ASSERT_EQ(runSph("run " + pipe() + " --duration " + duration + " --checkpoint-every " + every +
                   " --quiet --out " + run.string())
                .code,
            0);
  const fs::path newest = run / "checkpoints" / "checkpoint_00005.sphck";
  ASSERT_TRUE(fs::exists(newest));
  std::string bytes = readFile(newest);
  bytes[bytes.size() / 2] = char(bytes[bytes.size() / 2] ^ 0x01);
  std::ofstream(newest, std::ios::binary) << bytes;
  const std::string stats = readFile(run / "stats.csv");

  const Result corrupted = runSph("run --resume " + run.string() + " --duration " + longer);
  EXPECT_EQ(corrupted.code, 2) << corrupted.output;
  EXPECT_NE(corrupted.output.find("checkpoint_00005.sphck"), std::string::npos) << corrupted.output;
  EXPECT_NE(corrupted.output.find("checksum"), std::string::npos) << corrupted.output;
  EXPECT_EQ(readFile(run / "stats.csv"), stats) << "a refused resume touches nothing";

  std::ofstream(newest, std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  const Result cut = runSph("run --resume " + run.string() + " --duration " + longer);
  EXPECT_EQ(cut.code, 2) << cut.output;
  EXPECT_NE(cut.output.find("cut short"), std::string::npos) << cut.output;

  // Without the damaged one, the run resumes from the one before.
  fs::remove(newest);
  const Result earlier =
      runSph("run --resume " + run.string() + " --duration " + longer + " --quiet");
  EXPECT_EQ(earlier.code, 0) << earlier.output;

  const Result none = runSph("run --resume " + dir_.string());
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.output.find("no checkpoint"), std::string::npos) << none.output;
  const Result withSet = runSph("run --resume " + run.string() + " --set fluid.viscosity.value=1");
  EXPECT_EQ(withSet.code, 2);
  EXPECT_NE(withSet.output.find("--set"), std::string::npos) << withSet.output;
}

}  // namespace
