// The public face of the scene reader (include/sph/scene_file.hpp), without JSON types.
#include "sph/scene_file.hpp"

#include <sstream>

#include <nlohmann/json.hpp>

#include "scene/json_input.hpp"
#include "scene/scene_loader.hpp"

namespace sph {

Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return scene::loadScene(file, overrides);
}

Scene parseScene(const std::string& jsonText, const std::string& sourceName,
                 const std::vector<std::string>& overrides) {
  std::istringstream in(jsonText);
  return scene::parseScene(scene::parseJson(in, sourceName), sourceName, overrides);
}

Scene validateScene(const Scene& scene) {
  return scene::validateScene(scene);
}

std::string sceneToJsonText(const Scene& scene) {
  return scene::sceneToJson(scene).dump(2);
}

}  // namespace sph
