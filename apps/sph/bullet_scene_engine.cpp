#include "sph/bullet_engine.hpp"

#include "scene_engine.hpp"

namespace sph::cli {
namespace {

class BulletSceneEngine : public SceneEngine {
 public:
  explicit BulletSceneEngine(std::unique_ptr<BulletEngine> engine) : engine_(std::move(engine)) {}
  void step() override { engine_->step(); }

 private:
  std::unique_ptr<BulletEngine> engine_;
};

}  // namespace

std::unique_ptr<SceneEngine> attachSceneEngine(const Scene& scene, Simulation& sim) {
  if (scene.objectEngine.type != ObjectEngineKind::Bullet || scene.objects.empty()) return nullptr;
  std::unique_ptr<BulletEngine> engine = BulletEngine::forScene(scene);
  engine->attachTo(sim);
  return std::make_unique<BulletSceneEngine>(std::move(engine));
}

}  // namespace sph::cli
