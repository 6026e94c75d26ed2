#include "io/scene_flow.hpp"

#include <cmath>
#include <string>

#include "io/scene_checks.hpp"
#include "sph/error.hpp"

namespace sph::io {
namespace {

// A key of the other shape is a mistake, not something to ignore.
void refuseOtherShapesKeys(const ObjectReader& in, EmitterShape shape) {
  const char* const disc[] = {"center", "radius", "direction"};
  const char* const rectangle[] = {"corner", "edge1", "edge2"};
  const auto& others = shape == EmitterShape::Disc ? rectangle : disc;
  for (const char* key : others) {
    if (!in.has(key)) continue;
    in.context().fail(
        in.keyPath(key),
        std::string("not a key of a ") + nameOf(shape, kEmitterShapeNames) +
            " emitter; its keys are name, shape, speed, start, end, " +
            (shape == EmitterShape::Disc ? "center, radius, direction" : "corner, edge1, edge2"));
  }
}

EmitterDesc readEmitter(const ObjectReader& in, std::size_t index) {
  EmitterDesc e;
  e.name = in.string("name", "emitter" + std::to_string(index));
  e.shape = in.choice("shape", e.shape, kEmitterShapeNames);
  refuseOtherShapesKeys(in, e.shape);
  if (e.shape == EmitterShape::Disc) {
    e.center = in.requiredVec3("center");
    if (!in.has("radius"))
      in.context().fail(in.keyPath("radius"), "required key is missing (a length in m)");
    e.radius = in.number("radius", e.radius, kPositive);
    e.direction = in.requiredVec3("direction");
  } else {
    e.corner = in.requiredVec3("corner");
    e.edge1 = in.requiredVec3("edge1");
    e.edge2 = in.requiredVec3("edge2");
  }
  if (!in.has("speed"))
    in.context().fail(in.keyPath("speed"), "required key is missing (a speed in m/s)");
  e.speed = in.number("speed", e.speed, kSpeed);
  e.start = in.number("start", e.start, kNonNegative);
  e.end = in.number("end", e.end, kPositive);
  return e;
}

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

std::vector<EmitterDesc> readEmitters(const ObjectReader& root) {
  std::vector<EmitterDesc> emitters;
  for (const ObjectReader& in : root.objectArray("emitters", /*required=*/false,
                                                 /*nonEmpty=*/false))
    emitters.push_back(readEmitter(in, emitters.size()));
  return emitters;
}

std::vector<OutletDesc> readOutlets(const ObjectReader& root) {
  std::vector<OutletDesc> outlets;
  for (const ObjectReader& in : root.objectArray("outlets", /*required=*/false,
                                                 /*nonEmpty=*/false)) {
    OutletDesc o;
    o.name = in.string("name", "outlet" + std::to_string(outlets.size()));
    o.box = readBox(in);
    outlets.push_back(o);
  }
  return outlets;
}

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

}  // namespace sph::io
