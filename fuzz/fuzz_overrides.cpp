// Any bytes as --set overrides, one per line (at most 8), on a valid scene: a checked scene or
// an InputError naming the override.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_loader.hpp"
#include "sph/error.hpp"

namespace {

const nlohmann::json& baseScene() {
  static const nlohmann::json scene = nlohmann::json::parse(R"({
    "name": "base",
    "domain": {"min": [0, 0, 0], "max": [1, 1, 1]},
    "fluid": {"spacing": 0.05, "blocks": [{"min": [0, 0, 0], "max": [0.5, 0.5, 0.5]}]},
    "walls": [{"type": "tank", "min": [0, 0, 0], "max": [1, 1, 1]},
              {"type": "sphere", "center": [0.7, 0.7, 0.7], "radius": 0.1}],
    "objects": [{"name": "box", "shape": {"type": "box", "center": [0.7, 0.2, 0.7],
                                          "half_extents": [0.1, 0.1, 0.1]}}],
    "probes": [{"name": "p", "type": "point", "position": [0.2, 0.2, 0.2]}]
  })");
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<std::string> overrides;
  for (std::string line; overrides.size() < 8 && std::getline(in, line);) overrides.push_back(line);
  try {
    sph::scene::parseScene(baseScene(), "base.json", overrides);
  } catch (const sph::InputError&) {
  }
  return 0;
}
