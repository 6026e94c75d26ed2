#include "checkpoint.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/frame_writer.hpp"
#include "io/scene_loader.hpp"
#include "sph/error.hpp"

#ifndef SPH_VERSION
#define SPH_VERSION "unknown"
#endif

namespace sph::cli {

namespace fs = std::filesystem;

namespace {

// The file: magic, the two parts' lengths, the header (JSON), the simulation's state, and a
// checksum over both parts.
constexpr char kMagic[8] = {'S', 'P', 'H', 'C', 'H', 'E', 'C', 'K'};
constexpr std::uint64_t kMostHeaderBytes = std::uint64_t(1) << 30;
constexpr const char* kExtension = ".sphck";

std::uint64_t fnv1a(std::uint64_t hash, const std::string& bytes) {
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}
constexpr std::uint64_t kFnvStart = 14695981039346656037ull;

void writeWord(std::ostream& out, std::uint64_t v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}

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
  throw InputError(file.string() + ": " + why +
                   "; an earlier checkpoint, if the run kept one, can be resumed once this file "
                   "is removed");
}

}  // namespace

fs::path checkpointDir(const fs::path& runDir) {
  return runDir / "checkpoints";
}

void writeCheckpoint(const fs::path& runDir, const Simulation& sim, const RunPosition& position,
                     double checkpointEvery) {
  nlohmann::json series = nlohmann::json::array();
  for (const auto& [time, file] : position.series) series.push_back({time, file});
  const nlohmann::json header = {{"sph_version", SPH_VERSION},
                                 {"scene_file", sim.scene().sourcePath},
                                 {"scene", io::sceneToJson(sim.scene())},
                                 {"checkpoint_every", checkpointEvery},
                                 {"time", sim.time()},
                                 {"steps", sim.stepCount()},
                                 {"frame", position.frame},
                                 {"stats_bytes", position.statsBytes},
                                 {"probes_bytes", position.probesBytes},
                                 {"series", series}};
  const std::string headerText = header.dump();
  std::ostringstream state;
  sim.saveState(state);
  const std::string stateBytes = state.str();

  std::error_code error;
  fs::create_directories(checkpointDir(runDir), error);
  if (error)
    throw OutputError("cannot create '" + checkpointDir(runDir).string() + "': " + error.message());
  char name[64];
  std::snprintf(name, sizeof name, "checkpoint_%05d%s", position.frame, kExtension);
  io::writeFileAtomically(checkpointDir(runDir) / name, [&](std::ostream& out) {
    out.write(kMagic, sizeof kMagic);
    writeWord(out, headerText.size());
    writeWord(out, stateBytes.size());
    out << headerText << stateBytes;
    writeWord(out, fnv1a(fnv1a(kFnvStart, headerText), stateBytes));
  });

  std::vector<fs::path> all = checkpointsIn(runDir);
  for (std::size_t k = 0; k + 2 < all.size(); ++k) fs::remove(all[k], error);
}

Checkpoint readLatestCheckpoint(const fs::path& runDir) {
  const std::vector<fs::path> all = checkpointsIn(runDir);
  if (all.empty())
    throw InputError(runDir.string() +
                     ": no checkpoint to resume from (a run makes them with --checkpoint-every T)");
  Checkpoint c;
  c.file = all.back();
  std::ifstream in(c.file, std::ios::binary);
  if (!in) refuse(c.file, "cannot be read");
  char magic[sizeof kMagic];
  std::uint64_t headerBytes = 0, stateBytes = 0;
  in.read(magic, sizeof magic);
  in.read(reinterpret_cast<char*>(&headerBytes), sizeof headerBytes);
  in.read(reinterpret_cast<char*>(&stateBytes), sizeof stateBytes);
  if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    refuse(c.file, "not an sph checkpoint");
  std::error_code error;
  const std::uintmax_t size = fs::file_size(c.file, error);
  const std::uintmax_t fixed = sizeof kMagic + 3 * sizeof(std::uint64_t);
  if (error || headerBytes > kMostHeaderBytes || size < fixed ||
      headerBytes + stateBytes != size - fixed)
    refuse(c.file, "cut short or corrupted: its lengths do not add up to its size");
  std::string headerText(headerBytes, '\0'), state(stateBytes, '\0');
  std::uint64_t checksum = 0;
  in.read(headerText.data(), std::streamsize(headerBytes));
  in.read(state.data(), std::streamsize(stateBytes));
  in.read(reinterpret_cast<char*>(&checksum), sizeof checksum);
  if (!in) refuse(c.file, "cut short");
  if (fnv1a(fnv1a(kFnvStart, headerText), state) != checksum)
    refuse(c.file, "corrupted: its checksum does not match its contents");

  try {
    const nlohmann::json header = nlohmann::json::parse(headerText);
    const std::string version = header.at("sph_version").get<std::string>();
    if (version != SPH_VERSION)
      refuse(c.file, "written by sph " + version + "; this is sph " SPH_VERSION);
    c.sceneFile = header.at("scene_file").get<std::string>();
    c.scene = header.at("scene");
    c.checkpointEvery = header.at("checkpoint_every").get<double>();
    c.time = header.at("time").get<double>();
    c.position.frame = header.at("frame").get<int>();
    c.position.statsBytes = header.at("stats_bytes").get<std::uintmax_t>();
    c.position.probesBytes = header.at("probes_bytes").get<std::uintmax_t>();
    for (const nlohmann::json& entry : header.at("series"))
      c.position.series.emplace_back(entry.at(0).get<double>(), entry.at(1).get<std::string>());
  } catch (const nlohmann::json::exception& e) {
    refuse(c.file, std::string("its header is not what this version writes (") + e.what() + ")");
  }
  if (c.position.frame != frameOf(c.file)) refuse(c.file, "its name and its frame disagree");
  c.state = std::move(state);
  return c;
}

}  // namespace sph::cli
