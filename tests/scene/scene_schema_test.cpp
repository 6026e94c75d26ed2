// Tests of src/scene/scene_schema: the nearest-key suggestion and key paths.
#include "scene/scene_schema.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_loader.hpp"

namespace sph::scene {
namespace {

const KeySchema& level(const std::string& key) {
  return sceneSchema().child(key);
}

TEST(SceneSchema, NearestKeyFindsTypos) {
  EXPECT_EQ(nearestKey("viscosty", level("fluid")), "viscosity");
  EXPECT_EQ(nearestKey("dampd_box", level("domain")), "damped_box");
  EXPECT_EQ(nearestKey("sapcing", level("fluid")), "spacing");  // a swap is one edit
  EXPECT_EQ(nearestKey("Spacing", level("fluid")), "spacing");
  EXPECT_EQ(nearestKey("gravty", sceneSchema()), "gravity");
  EXPECT_EQ(nearestKey("velocty", level("fluid").child("blocks").element()), "velocity");
}

TEST(SceneSchema, NearestKeyIgnoresDistantWords) {
  EXPECT_EQ(nearestKey("colour", level("output")), std::nullopt);
  EXPECT_EQ(nearestKey("xyz", level("fluid")), std::nullopt);
  EXPECT_EQ(nearestKey("fp", level("output")), "fps");
  EXPECT_EQ(nearestKey("f", level("output")), std::nullopt);
}

TEST(SceneSchema, UnknownKeyText) {
  EXPECT_EQ(unknownKeyText("fluid", "viscosty", level("fluid")),
            "unknown key fluid.viscosty (did you mean fluid.viscosity?)");
  EXPECT_EQ(unknownKeyText("failure", "limit", level("failure")),
            "unknown key failure.limit (keys of failure are: max_density_error, max_speed)");
}

TEST(SceneSchema, KeyPaths) {
  EXPECT_EQ(joinKey("", "fluid"), "fluid");
  EXPECT_EQ(joinIndex(joinKey("fluid", "blocks"), 2), "fluid.blocks[2]");
  EXPECT_TRUE(keyWithin("fluid.blocks[0].max", "fluid"));
  EXPECT_TRUE(keyWithin("fluid.blocks[0].max", "fluid.blocks"));
  EXPECT_TRUE(keyWithin("fluid.spacing", "fluid.spacing"));
  EXPECT_FALSE(keyWithin("fluid.spacing2", "fluid.spacing"));
  EXPECT_FALSE(keyWithin("fluid", "fluid.spacing"));
  EXPECT_FALSE(keyWithin("fluid", ""));
}

TEST(SceneSchema, EnumerationNames) {
  EXPECT_STREQ(nameOf(KernelKind::CubicSpline, kKernelNames), "cubic_spline");
  EXPECT_STREQ(nameOf(FrameFormat::None, kFormatNames), "none");
  EXPECT_STREQ(nameOf(EquationOfState::Tait, kEosNames), "tait");
}

void collectNames(const KeySchema& key, std::set<std::string>& names) {
  if (!key.name.empty() && key.name != "[]") names.insert(key.name);
  for (const KeySchema& child : key.children) collectNames(child, names);
}

// The lines of the README's scene reference (its jsonc block), comments left out.
std::vector<std::string> readmeReferenceLines() {
  std::ifstream in(std::string(SPH_SOURCE_DIR) + "/README.md");
  std::string line;
  bool inside = false;
  std::vector<std::string> lines;
  while (std::getline(in, line)) {
    if (!inside) {
      inside = line.rfind("```jsonc", 0) == 0;
      continue;
    }
    if (line.rfind("```", 0) == 0) break;
    const std::size_t comment = line.find("//");
    if (comment != std::string::npos) line.erase(comment);
    lines.push_back(line);
  }
  return lines;
}

// Every name written as a key ("name": ...) in the README's scene reference.
std::set<std::string> readmeReferenceKeys() {
  std::set<std::string> keys;
  for (std::string line : readmeReferenceLines()) {
    for (std::size_t at = line.find('"'); at != std::string::npos; at = line.find('"', at + 1)) {
      const std::size_t end = line.find('"', at + 1);
      if (end == std::string::npos) break;
      std::size_t next = end + 1;
      while (next < line.size() && line[next] == ' ') ++next;
      if (next < line.size() && line[next] == ':') keys.insert(line.substr(at + 1, end - at - 1));
      at = end;
    }
  }
  return keys;
}

// The README's reference of every key and the schema the loader reads by name the same keys: a
// key added to one and not the other fails here.
TEST(SceneSchema, TheReadmeReferenceNamesEveryKeyAndNoOther) {
  std::set<std::string> schema;
  collectNames(sceneSchema(), schema);
  const std::set<std::string> readme = readmeReferenceKeys();
  ASSERT_FALSE(readme.empty()) << "no ```jsonc block in README.md";
  for (const std::string& key : schema)
    EXPECT_TRUE(readme.count(key)) << "the README's scene reference does not show " << key;
  for (const std::string& key : readme)
    EXPECT_TRUE(schema.count(key))
        << "the README's scene reference shows " << key << ", which no scene reads";
}

}  // namespace
}  // namespace sph::scene

namespace sph::scene {
namespace {

using nlohmann::json;

// The README's scene reference as JSON, the points it leaves to the reader ([x, y, z], [..]) as
// zeros.
json readmeReference() {
  std::string text;
  for (const std::string& line : readmeReferenceLines()) text += line + "\n";
  text = std::regex_replace(text, std::regex(R"(\[x, y, z\]|\[\.\.\])"), "[0, 0, 0]");
  return json::parse(text);
}

template <class Enum, std::size_t N>
Enum named(const json& value, const NamedValue<Enum> (&names)[N]) {
  for (const auto& n : names)
    if (value == n.name) return n.value;
  ADD_FAILURE() << "the README names an unknown type " << value;
  return names[0].value;
}

// A scene of defaults whose lists hold as many elements as the README's, each of the type the
// README shows, so that the two can be compared key by key.
Scene defaultsShapedLike(const json& readme) {
  Scene scene;
  scene.fluid.blocks.resize(readme["fluid"]["blocks"].size());
  for (const json& w : readme["walls"]) {
    WallDesc wall;
    wall.kind = named(w["type"], kWallKindNames);
    scene.walls.push_back(wall);
  }
  for (const json& o : readme["objects"]) {
    ObjectDesc object;
    object.deformable.pinned.resize(o["deformable"]["pinned"].size());
    object.deformable.cuts.resize(o["deformable"]["cuts"].size());
    object.keyframes.resize(o["keyframes"].size());
    scene.objects.push_back(object);
  }
  for (const json& p : readme["probes"]) {
    ProbeDesc probe;
    probe.kind = named(p["type"], kProbeKindNames);
    scene.probes.push_back(probe);
  }
  for (const json& e : readme["emitters"]) {
    EmitterDesc emitter;
    emitter.shape = named(e["shape"], kEmitterShapeNames);
    scene.emitters.push_back(emitter);
  }
  scene.outlets.resize(readme["outlets"].size());
  return scene;
}

// Each value the README shows is the default the declaration gives, except for keys that have
// none (the required ones) and names of the scene and of what a probe reads, which the README
// shows as examples.
void expectDefaults(const json& readme, const json& defaults, const KeySchema& schema,
                    const std::string& path) {
  if (schema.required) return;
  if (schema.shape == KeySchema::Shape::Object) {
    ASSERT_TRUE(readme.is_object()) << path;
    for (const auto& item : readme.items()) {
      const std::string& key = item.key();
      if (key == "name" || key == "description" || key == "object" || key == "wall") continue;
      const KeySchema* child = schema.find(key);
      ASSERT_NE(child, nullptr) << joinKey(path, key);
      ASSERT_TRUE(defaults.contains(key)) << joinKey(path, key);
      expectDefaults(item.value(), defaults[key], *child, joinKey(path, key));
    }
  } else if (schema.shape == KeySchema::Shape::Array &&
             schema.element().shape == KeySchema::Shape::Object) {
    ASSERT_EQ(readme.size(), defaults.size()) << path;
    for (std::size_t i = 0; i < readme.size(); ++i)
      expectDefaults(readme[i], defaults[i], schema.element(), joinIndex(path, i));
  } else if (readme.is_number() && defaults.is_number()) {
    EXPECT_EQ(readme.get<double>(), defaults.get<double>()) << "the README shows " << path;
  } else {
    EXPECT_EQ(readme, defaults) << "the README shows " << path;
  }
}

// The README's reference and the declarations agree on every default the README shows: a
// default changed in one place and not the other fails here.
TEST(SceneSchema, TheReadmeReferenceShowsTheDeclaredDefaults) {
  const json readme = readmeReference();
  expectDefaults(readme, sceneToJson(defaultsShapedLike(readme)), sceneSchema(), "");
}

}  // namespace
}  // namespace sph::scene
