// A scene's objects as Bullet bodies (object_engine.type "bullet"), and its walls as the fixed
// boxes they collide with: Bullet does not see the fluid's boundary particles.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "objects/mesh.hpp"
#include "sph/bullet_engine.hpp"
#include "sph/core/constants.hpp"
#include "sph/error.hpp"

namespace sph {
namespace {

using Vec3d = BulletEngine::Vec3d;

// The slabs around a box's inside, `thickness` thick: a floor, four sides and, if `lid`, a lid.
void addHollowBox(BulletEngine& engine, const AxisBox& inner, bool lid, double thickness) {
  const double t = thickness;
  Vec3d centre, half;
  for (int a = 0; a < 3; ++a) {
    centre[a] = 0.5 * (inner.min[a] + inner.max[a]);
    half[a] = 0.5 * (inner.max[a] - inner.min[a]);
  }
  for (int a = 0; a < 3; ++a) {
    for (int side = 0; side < 2; ++side) {
      if (a == 1 && side == 1 && !lid) continue;
      Vec3d c = centre, h = half;
      for (int b = 0; b < 3; ++b)
        if (b != a) h[b] += t;  // the slabs overlap at the edges: no gap there
      h[a] = 0.5 * t;
      c[a] = side == 0 ? inner.min[a] - 0.5 * t : inner.max[a] + 0.5 * t;
      engine.addStaticBox(h, c);
    }
  }
}

std::vector<Vec3d> meshVertices(const Scene& scene, const ShapeDesc& shape,
                                const std::string& where) {
  std::filesystem::path file = shape.meshFile;
  if (file.is_relative()) file = std::filesystem::path(scene.sourcePath).parent_path() / file;
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error))
    throw InputError(where + ".shape.file: no such file: " + file.string());
  std::vector<Vec3d> out;
  for (const Vec3& v : objects::loadMesh(file).vertices)
    out.push_back({v.x * shape.scale, v.y * shape.scale, v.z * shape.scale});
  return out;
}

bool isZero(const Vec3d& v) {
  return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
}

}  // namespace

std::unique_ptr<BulletEngine> BulletEngine::forScene(const Scene& scene) {
  Settings settings;
  settings.spacing = scene.fluid.spacing;
  settings.gravity = scene.gravity;
  settings.ownThread = scene.objectEngine.ownThread;
  // Faster than the fluid: more Bullet steps a fluid step; slower: the caller steps Bullet
  // after every 1/rate fluid steps (stepsBetween).
  settings.leastSubsteps = std::max(1, int(std::lround(scene.objectEngine.rate)));
  auto engine = std::make_unique<BulletEngine>(settings);
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const ObjectDesc& object = scene.objects[o];
    const ShapeDesc& shape = object.shape;
    const std::string where = scene.sourcePath + ": objects[" + std::to_string(o) + "]";
    const auto refuse = [&](const std::string& key, const std::string& what) {
      throw InputError(where + "." + key + ": " + what + " (object_engine.type \"bullet\")");
    };
    if (object.spacing != 0.0 && object.spacing != scene.fluid.spacing)
      refuse("spacing", "expected the fluid's spacing: Bullet's bodies are sampled at it");
    int id = -1;
    if (object.motion == ObjectMotion::Rigid) {
      switch (shape.kind) {
        case ShapeKind::Box:
          id = engine->addBox(shape.halfExtents, shape.center, object.density);
          break;
        case ShapeKind::Sphere:
          id = engine->addSphere(shape.radius, shape.center, object.density);
          break;
        case ShapeKind::Capsule: {
          const Vec3d& a = shape.axis;
          if (a[0] != 0.0 || a[2] != 0.0) refuse("shape.axis", "expected a capsule along y");
          id = engine->addCapsule(shape.radius, shape.length, shape.center, object.density);
          break;
        }
        case ShapeKind::Mesh:
          id = engine->addConvexHull(meshVertices(scene, shape, where), shape.center,
                                     object.density);
          break;
        case ShapeKind::Tube:
          refuse("shape.type", "expected a box, sphere, capsule or mesh for a rigid body");
      }
    } else if (object.motion == ObjectMotion::Deformable) {
      if (shape.kind != ShapeKind::Sphere)
        refuse("shape.type", "expected a sphere for a deformable (a soft ball)");
      const DeformableDesc& d = object.deformable;
      if (d.stiffness != 0.0 || d.damping != 0.0 || d.bendingStiffness != 0.0)
        refuse("deformable",
               "Bullet's soft balls take their own material: expected no "
               "stiffness, damping or bending_stiffness");
      if (!d.cuts.empty()) refuse("deformable.cuts", "not supported: expected none");
      SoftMaterial material;
      material.breakingStrain = d.breakingStrain;
      // A ball that tears has nothing to keep its volume with (soft_bodies.cpp).
      material.volumeStiffness = d.breakingStrain > 0.0 ? 0.0 : 0.5;
      material.bendingStiffness = 0.2;
      const double mass = object.density * 4.0 * kPi * shape.radius * shape.radius *
                          scene.fluid.spacing;  // a surface layer a spacing thick
      id = engine->addSoftBall(shape.radius, shape.center, mass, material);
      for (const AxisBox& box : d.pinned) engine->pinNodes(id, box);
    } else {
      refuse("motion",
             "expected \"rigid\" or \"deformable\": kinematic objects are the "
             "built-in engine's");
    }
    if (!isZero(object.velocity) || !isZero(object.angularVelocity))
      engine->setVelocity(id, object.velocity, object.angularVelocity);
  }
  const double thickness = 1.0;  // m: more than any body falls through in a substep
  for (const WallDesc& wall : scene.walls) {
    if (wall.kind == WallKind::Tank) addHollowBox(*engine, wall.box, wall.closed, thickness);
    if (wall.kind == WallKind::Box && wall.fluid == FluidSide::Inside)
      addHollowBox(*engine, wall.box, true, thickness);
    if (wall.kind == WallKind::Box && wall.fluid == FluidSide::Outside) {
      Vec3d centre, half;
      for (int a = 0; a < 3; ++a) {
        centre[a] = 0.5 * (wall.box.min[a] + wall.box.max[a]);
        half[a] = 0.5 * (wall.box.max[a] - wall.box.min[a]);
      }
      engine->addStaticBox(half, centre);
    }
  }
  return engine;
}

}  // namespace sph
