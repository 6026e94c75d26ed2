// A checkpoint file's bytes (checkpoint.hpp): the magic word "SPHCHECK", the lengths of its two
// parts, the header (JSON: the scene and where the run's outputs stood), the simulation's state
// (Simulation::saveState), and an FNV-1a checksum over both parts.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace sph::cli {

// Where the run's outputs stood when the checkpoint was taken.
struct RunPosition {
  int frame = 0;  // the index of the last frame written
  std::uintmax_t statsBytes = 0;
  std::uintmax_t probesBytes = 0;                      // 0: no probes.csv yet
  std::vector<std::pair<double, std::string>> series;  // frames.pvd: time, file
};

struct Checkpoint {
  std::filesystem::path file;
  std::string sceneFile;  // where the scene was read from, for messages
  nlohmann::json scene;   // resolved (scene::sceneToJson)
  double checkpointEvery = 0.0;
  double time = 0.0;  // simulated, s
  // How far the run went past it: a run that ends between two frames of its frame rate keeps
  // the checkpoint of its last whole frame (run_command.cpp); time otherwise.
  double reached = 0.0;
  RunPosition position;
  std::string state;  // Simulation::saveState's bytes
};

// The file's bytes for a header and a state.
std::string checkpointBytes(const nlohmann::json& header, const std::string& state);

// The checkpoint in `bytes`, read from `file` (for messages). Throws InputError naming the file
// and why it is refused: not a checkpoint, cut short, its lengths or checksum wrong, written by
// another version of sph, or a header without the fields this version writes or with values
// no run writes.
Checkpoint parseCheckpoint(const std::string& bytes, const std::filesystem::path& file);

}  // namespace sph::cli
