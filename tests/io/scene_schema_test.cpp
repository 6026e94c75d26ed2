// Tests of src/io/scene_schema: the nearest-key suggestion and key paths.
#include "io/scene_schema.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace sph::io {
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
            "unknown key failure.limit (keys of failure are: max_density_error)");
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

// Every name written as a key ("name": ...) in the README's scene reference (its jsonc block),
// comments left out.
std::set<std::string> readmeReferenceKeys() {
  std::ifstream in(std::string(SPH_SOURCE_DIR) + "/README.md");
  std::string line;
  bool inside = false;
  std::set<std::string> keys;
  while (std::getline(in, line)) {
    if (!inside) {
      inside = line.rfind("```jsonc", 0) == 0;
      continue;
    }
    if (line.rfind("```", 0) == 0) break;
    const std::size_t comment = line.find("//");
    if (comment != std::string::npos) line.erase(comment);
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
}  // namespace sph::io
