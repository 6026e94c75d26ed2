#include "scene/scene_flow.hpp"

#include <cmath>
#include <string>

#include "scene/scene_checks.hpp"
#include "sph/error.hpp"

namespace sph::scene {
namespace {

void checkEmitter(const ReadContext& context, const EmitterDesc& e, const std::string& path,
                  const Scene& scene) {
  const double spacing = scene.fluid.spacing;
  const AxisBox& domain = scene.domain.box;
  if (e.shape == EmitterShape::Disc) {
    checkPointInDomain(context, e.center, joinKey(path, "center"), domain);
    checkAtLeastSpacing(context, e.radius, joinKey(path, "radius"), spacing);
    const double length = lengthOf(e.direction);
    if (!(length > 0.0) || !std::isfinite(length))
      context.fail(joinKey(path, "direction"),
                   "expected a direction, got " + formatVec3(e.direction));
  } else {
    checkPointInDomain(context, e.corner, joinKey(path, "corner"), domain);
    checkAtLeastSpacing(context, lengthOf(e.edge1), joinKey(path, "edge1"), spacing);
    checkAtLeastSpacing(context, lengthOf(e.edge2), joinKey(path, "edge2"), spacing);
    checkNotParallel(context, e.edge1, e.edge2, joinKey(path, "edge1"), joinKey(path, "edge2"));
    const Vec3d far{e.corner[0] + e.edge1[0] + e.edge2[0], e.corner[1] + e.edge1[1] + e.edge2[1],
                    e.corner[2] + e.edge1[2] + e.edge2[2]};
    checkPointInDomain(context, far, joinKey(path, "edge2"), domain);
  }
  if (!(e.end > e.start))
    context.fail(joinKey(path, "end"),
                 "expected a time after " + joinKey(path, "start") + " " + formatNumber(e.start) +
                     " s, got " + formatNumber(e.end),
                 {joinKey(path, "start")});
}

}  // namespace

void checkFlow(const ReadContext& context, const Scene& scene) {
  if (scene.emitters.size() > kMaxEmitters)
    context.fail("emitters", "expected at most " + std::to_string(kMaxEmitters) +
                                 " emitters, got " + std::to_string(scene.emitters.size()));
  if (scene.outlets.size() > kMaxOutlets)
    context.fail("outlets", "expected at most " + std::to_string(kMaxOutlets) + " outlets, got " +
                                std::to_string(scene.outlets.size()));
  checkNames(context, scene.emitters, "emitters", "emitter");
  checkNames(context, scene.outlets, "outlets", "outlet");
  for (std::size_t i = 0; i < scene.emitters.size(); ++i)
    checkEmitter(context, scene.emitters[i], joinIndex("emitters", i), scene);
  for (std::size_t i = 0; i < scene.outlets.size(); ++i) {
    const std::string path = joinIndex("outlets", i);
    checkBoxOrder(context, scene.outlets[i].box, path);
    checkInsideDomain(context, scene.outlets[i].box, path, scene.domain.box);
  }
}

}  // namespace sph::scene
