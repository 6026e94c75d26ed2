// sceneToJson: the resolved scene in the scene-file schema, for summary.json and round trips,
// written by the same declarations the loader reads by (scene_keys.cpp).
#include <nlohmann/json.hpp>

#include "scene/scene_keys.hpp"
#include "scene/scene_loader.hpp"

namespace sph::scene {

nlohmann::json sceneToJson(const Scene& scene) {
  return writeKeys(scene, sceneKeys());
}

}  // namespace sph::scene
