// The public face of the scene reader (include/sph/scene_file.hpp), without JSON types.
#include "sph/scene_file.hpp"

#include <sstream>

#include <nlohmann/json.hpp>

#include "io/json_input.hpp"
#include "io/scene_loader.hpp"

namespace sph {

Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return io::loadScene(file, overrides);
}

Scene parseScene(const std::string& jsonText, const std::string& sourceName,
                 const std::vector<std::string>& overrides) {
  std::istringstream in(jsonText);
  return io::parseScene(io::parseJson(in, sourceName), sourceName, overrides);
}

std::string sceneToJsonText(const Scene& scene) {
  return io::sceneToJson(scene).dump(2);
}

}  // namespace sph
