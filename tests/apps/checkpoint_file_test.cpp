// The checkpoint file's bytes (apps/sph/checkpoint_file.hpp): what is written reads back, and a
// header whose values no run writes is refused naming the file, however its checksum reads.
#include "checkpoint_file.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "sph/error.hpp"

namespace sph::cli {
namespace {

nlohmann::json header() {
  return {{"sph_version", SPH_VERSION},
          {"scene_file", "scenes/drop.json"},
          {"scene", {{"name", "drop"}}},
          {"checkpoint_every", 0.1},
          {"time", 0.5},
          {"steps", 120},
          {"frame", 25},
          {"stats_bytes", 4096},
          {"probes_bytes", 0},
          {"series", {{0.0, "frames/frame_00000.vtp"}, {0.02, "frames/frame_00001.vtp"}}}};
}

std::string refusal(const nlohmann::json& h, const std::string& state = "state bytes") {
  try {
    parseCheckpoint(checkpointBytes(h, state), "run/checkpoints/checkpoint_00025.sphck");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(CheckpointFile, ReadsBackWhatItWrites) {
  const Checkpoint c = parseCheckpoint(checkpointBytes(header(), std::string("\0state", 6)),
                                       "checkpoint_00025.sphck");
  EXPECT_EQ(c.sceneFile, "scenes/drop.json");
  EXPECT_EQ(c.scene["name"], "drop");
  EXPECT_EQ(c.checkpointEvery, 0.1);
  EXPECT_EQ(c.time, 0.5);
  EXPECT_EQ(c.position.frame, 25);
  EXPECT_EQ(c.position.statsBytes, 4096u);
  ASSERT_EQ(c.position.series.size(), 2u);
  EXPECT_EQ(c.position.series[1].second, "frames/frame_00001.vtp");
  EXPECT_EQ(c.state, std::string("\0state", 6));
}

TEST(CheckpointFile, HeaderValuesNoRunWritesAreRefused) {
  EXPECT_EQ(refusal(header()), "accepted");
  for (const auto& [key, value] :
       std::initializer_list<std::pair<const char*, nlohmann::json>>{{"frame", 1e300},
                                                                     {"frame", -1},
                                                                     {"frame", 100000},
                                                                     {"time", -0.5},
                                                                     {"checkpoint_every", "often"},
                                                                     {"stats_bytes", -4096},
                                                                     {"series", 3},
                                                                     {"series", {{0.0}}},
                                                                     {"scene", 7},
                                                                     {"sph_version", "0.0.1"}}) {
    nlohmann::json h = header();
    h[key] = value;
    const std::string message = refusal(h);
    EXPECT_EQ(message.rfind("run/checkpoints/checkpoint_00025.sphck: ", 0), 0u)
        << key << ": " << message;
  }
  nlohmann::json missing = header();
  missing.erase("time");
  EXPECT_NE(refusal(missing).find("its header is not what this version writes"), std::string::npos);
}

// Lengths whose sum wraps past 2^64 to the file's size once passed the size check, and the
// reader then asked for a string of 2^64 - 1 bytes.
TEST(CheckpointFile, LengthsThatDoNotAddUpAreRefused) {
  std::string bytes = checkpointBytes(header(), "state");
  const std::uint64_t parts = bytes.size() - 32;  // magic, two lengths, checksum
  const std::uint64_t headerBytes = parts + 1, stateBytes = ~std::uint64_t(0);
  std::memcpy(bytes.data() + 8, &headerBytes, 8);
  std::memcpy(bytes.data() + 16, &stateBytes, 8);
  try {
    parseCheckpoint(bytes, "c.sphck");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lengths do not add up"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseCheckpoint("SPHCHECK", "c.sphck"), InputError);
  EXPECT_THROW(parseCheckpoint(std::string(40, '\0'), "c.sphck"), InputError);
}

}  // namespace
}  // namespace sph::cli
