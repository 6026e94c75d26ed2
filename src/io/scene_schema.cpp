#include "io/scene_schema.hpp"

#include <algorithm>
#include <utility>

namespace sph::io {
namespace {

using Shape = KeySchema::Shape;

KeySchema value(std::string name) {
  return {std::move(name), Shape::Value, {}};
}

KeySchema object(std::string name, std::vector<KeySchema> keys) {
  return {std::move(name), Shape::Object, std::move(keys)};
}

KeySchema vec3(std::string name) {
  return {std::move(name), Shape::Array, {value("[]")}};
}

KeySchema arrayOf(std::string name, std::vector<KeySchema> elementKeys) {
  return {std::move(name), Shape::Array, {object("[]", std::move(elementKeys))}};
}

KeySchema buildSchema() {
  return object(
      "",
      {value("name"), value("description"),
       object("domain", {vec3("min"), vec3("max"), value("outside"), value("damped_box"),
                         value("damping"), value("periodic")}),
       vec3("gravity"),
       object("fluid",
              {value("rest_density"), value("spacing"), value("support_ratio"), value("solver"),
               object("dfsph",
                      {value("density_tolerance"), value("divergence_tolerance"),
                       value("min_iterations"), value("max_iterations"), value("warm_start"),
                       value("divergence_solve"), value("density_solve"), value("force_factor")}),
               value("kernel"), value("eos"), value("clamp_negative_pressure"),
               value("pressure_form"), value("density"), value("density_diffusion"),
               object("viscosity", {value("model"), value("value"), value("wall_friction")}),
               object("surface_tension", {value("coefficient"), value("threshold")}),
               arrayOf("blocks", {vec3("min"), vec3("max"), vec3("velocity"), value("hydrostatic"),
                                  value("inside"), vec3("angular_velocity")})}),
       arrayOf("walls",
               {value("name"), value("type"), value("layers"), vec3("min"), vec3("max"),
                value("closed"), value("fluid"), vec3("center"), value("radius"), value("length"),
                vec3("axis"), value("capped"), vec3("corner"), vec3("edge1"), vec3("edge2"),
                value("file"), value("scale"), value("open")}),
       arrayOf("objects",
               {value("name"), value("motion"),
                object("shape", {value("type"), vec3("center"), vec3("half_extents"),
                                 value("radius"), value("length"), vec3("axis"), value("capped"),
                                 value("file"), value("scale"), value("solid"), value("layers")}),
                value("density"), value("spacing"), vec3("velocity"), vec3("angular_velocity"),
                object("deformable",
                       {value("stiffness"), value("damping"), value("breaking_strain"),
                        value("spring_reach"), arrayOf("pinned", {vec3("min"), vec3("max")}),
                        arrayOf("cuts", {vec3("min"), vec3("max")}), value("model"),
                        value("substeps"), value("bending_stiffness")}),
                arrayOf("keyframes", {value("time"), vec3("offset"), vec3("rotation")})}),
       object("interaction",
              {value("coupling"), value("influence_ratio"), value("distance_exponent"),
               value("stiffness"), value("damping"), value("shear"), value("max_acceleration"),
               value("cut_aware_damping")}),
       object("object_engine", {value("type"), value("rate"), value("own_thread")}),
       object("calibration", {value("mass"), value("max_expected_speed"), value("speed_of_sound"),
                              value("stiffness")}),
       object("time", {value("duration"), value("cfl"), value("force_factor"),
                       value("viscous_factor"), value("max_dt"), value("fixed_dt")}),
       object("output", {value("fps"), value("format"), value("probe_rate")}),
       arrayOf("probes", {value("name"), value("type"), vec3("position"), vec3("from"), vec3("to"),
                          value("object"), value("wall")}),
       arrayOf("emitters", {value("name"), value("shape"), vec3("center"), value("radius"),
                            vec3("direction"), vec3("corner"), vec3("edge1"), vec3("edge2"),
                            value("speed"), value("start"), value("end")}),
       arrayOf("outlets", {value("name"), vec3("min"), vec3("max")}),
       object("failure", {value("max_density_error")}),
       object("limits", {value("max_particles"), value("max_memory_gb")})});
}

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbouring characters each cost 1, so "sapcing" is as close to "spacing" as "spacng".
std::size_t editDistance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::size_t> d((n + 1) * (m + 1));
  auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * (m + 1) + j]; };
  for (std::size_t i = 0; i <= n; ++i) at(i, 0) = i;
  for (std::size_t j = 0; j <= m; ++j) at(0, j) = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
      }
    }
  }
  return at(n, m);
}

}  // namespace

const KeySchema* KeySchema::find(const std::string& key) const {
  if (shape != Shape::Object) return nullptr;
  for (const KeySchema& c : children) {
    if (c.name == key) return &c;
  }
  return nullptr;
}

const KeySchema& KeySchema::child(const std::string& key) const {
  const KeySchema* found = find(key);
  if (found == nullptr) throw std::logic_error("scene schema has no key '" + key + "'");
  return *found;
}

const KeySchema& sceneSchema() {
  static const KeySchema schema = buildSchema();
  return schema;
}

std::string joinKey(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string joinIndex(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

bool keyWithin(const std::string& inner, const std::string& outer) {
  if (inner.size() == outer.size()) return inner == outer;
  return !outer.empty() && inner.size() > outer.size() &&
         inner.compare(0, outer.size(), outer) == 0 &&
         (inner[outer.size()] == '.' || inner[outer.size()] == '[');
}

std::optional<std::string> nearestKey(const std::string& key, const KeySchema& level) {
  std::optional<std::string> best;
  std::size_t bestDistance = 0;
  for (const KeySchema& candidate : level.children) {
    const std::size_t distance = editDistance(key, candidate.name);
    // About one edit in three characters still reads as a typo; more is a different word.
    const std::size_t tolerance = std::max<std::size_t>(1, candidate.name.size() / 3);
    if (distance <= tolerance && (!best || distance < bestDistance)) {
      best = candidate.name;
      bestDistance = distance;
    }
  }
  return best;
}

std::string unknownKeyText(const std::string& parentPath, const std::string& key,
                           const KeySchema& level) {
  std::string text = "unknown key " + joinKey(parentPath, key);
  if (const auto suggestion = nearestKey(key, level)) {
    return text + " (did you mean " + joinKey(parentPath, *suggestion) + "?)";
  }
  text += parentPath.empty() ? " (top-level keys are: " : " (keys of " + parentPath + " are: ";
  for (std::size_t i = 0; i < level.children.size(); ++i) {
    text += (i == 0 ? "" : ", ") + level.children[i].name;
  }
  return text + ")";
}

const std::vector<std::string>& wallKeys(WallKind kind) {
  static const std::vector<std::string> tank{"min", "max", "closed"};
  static const std::vector<std::string> box{"min", "max", "fluid"};
  static const std::vector<std::string> sphere{"center", "radius", "fluid"};
  static const std::vector<std::string> cylinder{"center", "radius", "length",
                                                 "axis",   "capped", "fluid"};
  static const std::vector<std::string> plane{"corner", "edge1", "edge2"};
  static const std::vector<std::string> mesh{"file", "center", "scale", "open"};
  switch (kind) {
    case WallKind::Tank:
      return tank;
    case WallKind::Box:
      return box;
    case WallKind::Sphere:
      return sphere;
    case WallKind::Cylinder:
      return cylinder;
    case WallKind::Plane:
      return plane;
    case WallKind::Mesh:
      break;
  }
  return mesh;
}

}  // namespace sph::io
