#include "checkpoint.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "sph/error.hpp"
#include "sph/io/frame_writer.hpp"
#include "sph/scene_file.hpp"

#ifndef SPH_VERSION
#define SPH_VERSION "unknown"
#endif

namespace sph::cli {

namespace fs = std::filesystem;

namespace {

constexpr const char* kExtension = ".sphck";
constexpr std::uintmax_t kLargestFile = std::uintmax_t(64) << 30;

// The frame a checkpoint file was taken at, or -1 for a file that is not one.
int frameOf(const fs::path& file) {
  const std::string name = file.filename().string();
  const std::string prefix = "checkpoint_";
  if (name.size() != prefix.size() + 5 + std::strlen(kExtension) ||
      name.compare(0, prefix.size(), prefix) != 0 || file.extension() != kExtension)
    return -1;
  int frame = 0;
  for (std::size_t k = prefix.size(); k < prefix.size() + 5; ++k) {
    if (name[k] < '0' || name[k] > '9') return -1;
    frame = frame * 10 + (name[k] - '0');
  }
  return frame;
}

// The run's checkpoints, oldest first.
std::vector<fs::path> checkpointsIn(const fs::path& runDir) {
  std::vector<fs::path> found;
  std::error_code error;
  for (fs::directory_iterator it(checkpointDir(runDir), error), end; !error && it != end;
       it.increment(error))
    if (it->is_regular_file(error) && frameOf(it->path()) >= 0) found.push_back(it->path());
  std::sort(found.begin(), found.end(),
            [](const fs::path& a, const fs::path& b) { return frameOf(a) < frameOf(b); });
  return found;
}

[[noreturn]] void refuse(const fs::path& file, const std::string& why) {
  throw InputError(file.string() + ": " + why);
}

}  // namespace

fs::path checkpointDir(const fs::path& runDir) {
  return runDir / "checkpoints";
}

PendingCheckpoint makeCheckpoint(const Simulation& sim, const RunPosition& position,
                                 double checkpointEvery, double reached) {
  nlohmann::json series = nlohmann::json::array();
  for (const auto& [time, file] : position.series) series.push_back({time, file});
  // Where the scene was read from, whole, so that a resume from another folder finds its meshes.
  std::error_code sourceError;
  const fs::path source = sim.scene().sourcePath;
  const fs::path sceneFile =
      fs::exists(source, sourceError) ? fs::absolute(source, sourceError) : source;
  const nlohmann::json header = {{"sph_version", SPH_VERSION},
                                 {"scene_file", sceneFile.string()},
                                 {"scene", nlohmann::json::parse(sceneToJsonText(sim.scene()))},
                                 {"checkpoint_every", checkpointEvery},
                                 {"time", sim.time()},
                                 {"reached", reached},
                                 {"steps", sim.stepCount()},
                                 {"frame", position.frame},
                                 {"stats_bytes", position.statsBytes},
                                 {"probes_bytes", position.probesBytes},
                                 {"series", series}};
  std::ostringstream state;
  sim.saveState(state);
  return {position.frame, checkpointBytes(header, state.str())};
}

void writeCheckpoint(const fs::path& runDir, const Simulation& sim, const RunPosition& position,
                     double checkpointEvery) {
  storeCheckpoint(runDir, makeCheckpoint(sim, position, checkpointEvery, sim.time()));
}

void storeCheckpoint(const fs::path& runDir, const PendingCheckpoint& checkpoint) {
  std::error_code error;
  fs::create_directories(checkpointDir(runDir), error);
  if (error)
    throw OutputError("cannot create '" + checkpointDir(runDir).string() + "': " + error.message());
  char name[64];
  std::snprintf(name, sizeof name, "checkpoint_%05d%s", checkpoint.frame, kExtension);
  io::writeFileAtomically(checkpointDir(runDir) / name, [&](std::ostream& out) {
    out.write(checkpoint.bytes.data(), std::streamsize(checkpoint.bytes.size()));
  });

  std::vector<fs::path> all = checkpointsIn(runDir);
  for (std::size_t k = 0; k + 2 < all.size(); ++k) fs::remove(all[k], error);
}

Checkpoint readLatestCheckpoint(const fs::path& runDir) {
  const std::vector<fs::path> all = checkpointsIn(runDir);
  if (all.empty())
    throw InputError(runDir.string() +
                     ": no checkpoint to resume from (a run makes them with --checkpoint-every T)");
  const fs::path file = all.back();
  std::error_code error;
  const std::uintmax_t size = fs::file_size(file, error);
  if (error) refuse(file, "cannot be read: " + error.message());
  if (size > kLargestFile) refuse(file, "is " + std::to_string(size) + " bytes, past any run's");
  std::ifstream in(file, std::ios::binary);
  std::string bytes(size, '\0');
  in.read(bytes.data(), std::streamsize(size));
  if (!in || in.gcount() != std::streamsize(size)) refuse(file, "cannot be read");
  Checkpoint c = parseCheckpoint(bytes, file);
  if (c.position.frame != frameOf(file))
    refuse(file, "its name and its frame disagree; expected the file its run wrote");
  return c;
}

}  // namespace sph::cli
