#include "checkpoint_file.hpp"

#include <cmath>
#include <cstring>

#include "sph/checksum.hpp"
#include "sph/error.hpp"

#ifndef SPH_VERSION
#define SPH_VERSION "unknown"
#endif

namespace sph::cli {

namespace {

constexpr char kMagic[8] = {'S', 'P', 'H', 'C', 'H', 'E', 'C', 'K'};
constexpr std::size_t kFixedBytes = sizeof kMagic + 3 * sizeof(std::uint64_t);
void appendWord(std::string& out, std::uint64_t v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

std::uint64_t wordAt(const std::string& bytes, std::size_t at) {
  std::uint64_t v = 0;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& why) {
  throw InputError(file.string() + ": " + why +
                   "; an earlier checkpoint, if the run kept one, can be resumed once this file "
                   "is removed");
}

// A header field of the type and range this version writes.
double finiteAtLeastZero(const nlohmann::json& header, const char* key) {
  const nlohmann::json& v = header.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0.0)
    throw std::invalid_argument(std::string(key) + " is not a number ≥ 0");
  return v.get<double>();
}
std::uint64_t count(const nlohmann::json& header, const char* key, std::uint64_t most) {
  const nlohmann::json& v = header.at(key);
  if (!v.is_number_unsigned() || v.get<std::uint64_t>() > most)
    throw std::invalid_argument(std::string(key) + " is not a count up to " + std::to_string(most));
  return v.get<std::uint64_t>();
}

}  // namespace

std::string checkpointBytes(const nlohmann::json& header, const std::string& state) {
  const std::string headerText = header.dump();
  std::string out(kMagic, sizeof kMagic);
  appendWord(out, headerText.size());
  appendWord(out, state.size());
  out += headerText;
  out += state;
  appendWord(out, fnv1a(state.data(), state.size(), fnv1a(headerText.data(), headerText.size())));
  return out;
}

Checkpoint parseCheckpoint(const std::string& bytes, const std::filesystem::path& file) {
  if (bytes.size() < kFixedBytes || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    refuse(file, "not an sph checkpoint");
  const std::uint64_t headerBytes = wordAt(bytes, sizeof kMagic);
  const std::uint64_t stateBytes = wordAt(bytes, sizeof kMagic + 8);
  const std::uint64_t parts = bytes.size() - kFixedBytes;
  if (headerBytes > parts || stateBytes != parts - headerBytes)
    refuse(file, "cut short or corrupted: its lengths do not add up to its size");
  const char* header = bytes.data() + sizeof kMagic + 16;
  const char* state = header + headerBytes;
  const std::uint64_t checksum = wordAt(bytes, bytes.size() - 8);
  if (fnv1a(state, stateBytes, fnv1a(header, headerBytes)) != checksum)
    refuse(file, "corrupted: its checksum does not match its contents");

  Checkpoint c;
  c.file = file;
  try {
    const nlohmann::json h = nlohmann::json::parse(header, header + headerBytes);
    const std::string version = h.at("sph_version").get<std::string>();
    if (version != SPH_VERSION)
      refuse(file, "written by sph " + version.substr(0, 40) + "; this is sph " SPH_VERSION);
    c.sceneFile = h.at("scene_file").get<std::string>();
    c.scene = h.at("scene");
    if (!c.scene.is_object()) throw std::invalid_argument("scene is not an object");
    c.checkpointEvery = finiteAtLeastZero(h, "checkpoint_every");
    c.time = finiteAtLeastZero(h, "time");
    c.reached = h.contains("reached") ? finiteAtLeastZero(h, "reached") : c.time;
    if (c.reached < c.time) throw std::invalid_argument("reached is before time");
    c.position.frame = int(count(h, "frame", 99999));
    c.position.statsBytes = count(h, "stats_bytes", std::uint64_t(1) << 50);
    c.position.probesBytes = count(h, "probes_bytes", std::uint64_t(1) << 50);
    const nlohmann::json& series = h.at("series");
    if (!series.is_array()) throw std::invalid_argument("series is not a list");
    for (const nlohmann::json& entry : series) {
      if (!entry.is_array() || entry.size() != 2 || !entry[0].is_number() || !entry[1].is_string())
        throw std::invalid_argument("a series entry is not [time, file]");
      c.position.series.emplace_back(entry[0].get<double>(), entry[1].get<std::string>());
    }
  } catch (const nlohmann::json::exception& e) {
    refuse(file, std::string("its header is not what this version writes (") + e.what() + ")");
  } catch (const std::invalid_argument& e) {
    refuse(file, std::string("its header is not what this version writes (") + e.what() + ")");
  }
  c.state.assign(state, stateBytes);
  return c;
}

}  // namespace sph::cli
