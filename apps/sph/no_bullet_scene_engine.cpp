#include "scene_engine.hpp"
#include "sph/error.hpp"

namespace sph::cli {

std::unique_ptr<SceneEngine> attachSceneEngine(const Scene& scene, Simulation&) {
  if (scene.objectEngine.type != ObjectEngineKind::Bullet || scene.objects.empty()) return nullptr;
  throw InputError(scene.sourcePath +
                   ": object_engine.type: \"bullet\", but this sph was built without Bullet "
                   "(install libbullet-dev and build again); expected \"builtin\"");
}

}  // namespace sph::cli
