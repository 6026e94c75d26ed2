#include "sph/bullet_engine.hpp"

#include <algorithm>
#include <cmath>

#include "scene_engine.hpp"

namespace sph::cli {
namespace {

class BulletSceneEngine : public SceneEngine {
 public:
  BulletSceneEngine(std::unique_ptr<BulletEngine> engine, double rate)
      : engine_(std::move(engine)),
        every_(rate < 1.0 ? std::max(1, int(std::lround(1.0 / rate))) : 1) {}
  // At a rate under 1, after every 1/rate fluid steps, over the forces of them all.
  void step() override {
    if (++steps_ % every_ == 0) engine_->step();
  }

 private:
  std::unique_ptr<BulletEngine> engine_;
  int every_;
  long long steps_ = 0;
};

}  // namespace

std::unique_ptr<SceneEngine> attachSceneEngine(const Scene& scene, Simulation& sim) {
  if (scene.objectEngine.type != ObjectEngineKind::Bullet || scene.objects.empty()) return nullptr;
  std::unique_ptr<BulletEngine> engine = BulletEngine::forScene(scene);
  engine->attachTo(sim);
  return std::make_unique<BulletSceneEngine>(std::move(engine), scene.objectEngine.rate);
}

}  // namespace sph::cli
