// The object engine a scene names outside the library: with object_engine.type "bullet", its
// Bullet world (sph/bullet_engine.hpp), attached to the simulation and stepped after each
// fluid step.
#pragma once

#include <memory>

#include "sph/scene.hpp"
#include "sph/simulation.hpp"

namespace sph::cli {

class SceneEngine {
 public:
  virtual ~SceneEngine() = default;
  virtual void step() = 0;  // after each of the fluid's steps
};

// Null for the built-in engine or a scene without objects. Throws InputError naming the
// scene's key when this sph was built without Bullet, or the object Bullet cannot take.
std::unique_ptr<SceneEngine> attachSceneEngine(const Scene& scene, Simulation& sim);

}  // namespace sph::cli
