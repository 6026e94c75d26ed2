// Tests of `--set dotted.key=value` overrides (src/scene/scene_overrides), through parseScene.
#include "scene/scene_overrides.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace sph::scene {
namespace {

using nlohmann::json;
using scene_test::completeSceneJson;
using scene_test::kSource;
using scene_test::minimalSceneJson;
using scene_test::parseError;

Scene parseWith(const json& document, const std::vector<std::string>& overrides) {
  return parseScene(document, kSource, overrides);
}

void expectContains(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}

TEST(SceneOverrides, ChangeValues) {
  const Scene scene = parseWith(
      completeSceneJson(),
      {"fluid.viscosity.value=0.07", "output.format=csv", "domain.damped_box=false", "name=renamed",
       "description=\"quoted, with = sign\"", "fluid.kernel = cubic_spline"});
  EXPECT_EQ(scene.fluid.viscosity, 0.07);
  EXPECT_EQ(scene.output.format, FrameFormat::Csv);
  EXPECT_FALSE(scene.domain.dampedBox);
  EXPECT_EQ(scene.name, "renamed");
  EXPECT_EQ(scene.description, "quoted, with = sign");
  EXPECT_EQ(scene.fluid.kernel, KernelKind::CubicSpline);
  EXPECT_EQ(scene.fluid.spacing, 0.02);  // untouched
}

TEST(SceneOverrides, DoNotChangeTheCallersDocument) {
  const json document = completeSceneJson();
  parseWith(document, {"fluid.spacing=0.05"});
  EXPECT_EQ(document, completeSceneJson());
}

TEST(SceneOverrides, IndexArrays) {
  const Scene scene = parseWith(completeSceneJson(),
                                {"fluid.blocks.0.max=[0.1,0.2,0.1]", "fluid.blocks.0.velocity.2=2",
                                 "gravity.1=-1.62", "walls.0.layers=1"});
  EXPECT_EQ(scene.fluid.blocks[0].box.max, (Vec3d{0.1, 0.2, 0.1}));
  EXPECT_EQ(scene.fluid.blocks[0].velocity, (Vec3d{1, 0, 2}));
  EXPECT_EQ(scene.gravity, (Vec3d{0, -1.62, 0.5}));
  EXPECT_EQ(scene.walls[0].layers, 1);
}

TEST(SceneOverrides, CreateMissingOptionalKeys) {
  // The minimal scene has no calibration, time or walls.
  const Scene scene =
      parseWith(minimalSceneJson(),
                {"calibration.speed_of_sound=40", "time.fixed_dt=0.001", "walls.0.min=[0,0,0]",
                 "walls.0.max=[1,1,1]", "fluid.blocks.1={\"min\":[0.6,0,0],\"max\":[1,0.2,0.2]}"});
  EXPECT_EQ(scene.calibration.speedOfSound, 40.0);
  EXPECT_FALSE(scene.calibration.mass.has_value());
  EXPECT_EQ(scene.time.fixedDt, 0.001);
  ASSERT_EQ(scene.walls.size(), 1u);
  EXPECT_EQ(scene.walls[0].box.max, (Vec3d{1, 1, 1}));
  ASSERT_EQ(scene.fluid.blocks.size(), 2u);
  EXPECT_EQ(scene.fluid.blocks[1].box.min, (Vec3d{0.6, 0, 0}));
}

TEST(SceneOverrides, NullUnsetsAnOptionalValue) {
  const Scene scene = parseWith(completeSceneJson(), {"calibration.mass=null"});
  EXPECT_FALSE(scene.calibration.mass.has_value());
}

TEST(SceneOverrides, LaterOverridesWin) {
  const Scene scene = parseWith(completeSceneJson(), {"fluid.spacing=-1", "fluid.spacing=0.04"});
  EXPECT_EQ(scene.fluid.spacing, 0.04);
}

TEST(SceneOverrides, UnknownKeySuggestsTheNearestKey) {
  EXPECT_EQ(parseError(completeSceneJson(), {"fluid.viscosty.value=0.05"}),
            "scenes/x.json: --set fluid.viscosty.value=0.05: unknown key fluid.viscosty (did "
            "you mean fluid.viscosity?)");
  EXPECT_EQ(parseError(completeSceneJson(), {"domain.dampd_box=true"}),
            "scenes/x.json: --set domain.dampd_box=true: unknown key domain.dampd_box (did you "
            "mean domain.damped_box?)");
  expectContains(parseError(completeSceneJson(), {"fluid.blocks.0.velocty=[0,0,0]"}),
                 {"unknown key fluid.blocks[0].velocty (did you mean fluid.blocks[0].velocity?)"});
  expectContains(parseError(completeSceneJson(), {"solver=pcisph"}),
                 {"scenes/x.json: --set solver=pcisph: unknown key solver (top-level keys are:"});
}

// A key an older version read says it was removed, rather than suggest another.
TEST(SceneOverrides, ARemovedKeySaysItWasRemoved) {
  EXPECT_EQ(parseError(completeSceneJson(), {"fluid.dfsph.chebyshev=0.8"}),
            "scenes/x.json: --set fluid.dfsph.chebyshev=0.8: fluid.dfsph.chebyshev: removed from "
            "sph: Chebyshev's weights on the density solve were measured and not kept "
            "(docs/experiments.md); delete the key");
}

TEST(SceneOverrides, KeysThatDoNotFitTheSchemaShape) {
  expectContains(parseError(completeSceneJson(), {"fluid.spacing.0=1"}),
                 {"scenes/x.json: --set fluid.spacing.0=1: fluid.spacing holds a single value"});
  expectContains(parseError(completeSceneJson(), {"fluid.blocks.first.min=[0,0,0]"}),
                 {"--set fluid.blocks.first.min=[0,0,0]: fluid.blocks is an array: expected an "
                  "index (0, 1, ...) after it, got \"first\""});
  expectContains(parseError(completeSceneJson(), {"fluid.0=1"}), {"unknown key fluid.0"});
}

TEST(SceneOverrides, IndexPastTheEnd) {
  expectContains(parseError(completeSceneJson(), {"fluid.blocks.5.max=[1,1,1]"}),
                 {"scenes/x.json: --set fluid.blocks.5.max=[1,1,1]: index 5 is past the end of "
                  "fluid.blocks, which has 2 elements"});
  expectContains(parseError(completeSceneJson(), {"gravity.3=1"}),
                 {"index 3 is past the end of gravity, which has 3 elements"});
}

TEST(SceneOverrides, MalformedOverride) {
  EXPECT_EQ(parseError(completeSceneJson(), {"fluid.spacing"}),
            "scenes/x.json: --set fluid.spacing: expected dotted.key=value");
  expectContains(parseError(completeSceneJson(), {"fluid..spacing=1"}),
                 {"--set fluid..spacing=1: expected dotted.key=value"});
  expectContains(parseError(completeSceneJson(), {"=1"}), {"--set =1: expected dotted.key"});
}

// Found by fuzz_overrides: bytes that are not UTF-8 became a string that no message could print
// (nlohmann's type_error 316 ended the process).
TEST(SceneOverrides, TextThatIsNotUtf8IsRefused) {
  EXPECT_EQ(parseError(completeSceneJson(), {"name=\xf5\x8f"}),
            "scenes/x.json: --set name=\xf5\x8f: expected UTF-8 text");
  EXPECT_EQ(parseError(completeSceneJson(), {"walls.2.radius=0.\xce\xf5"}),
            "scenes/x.json: --set walls.2.radius=0.\xce\xf5: expected UTF-8 text");
}

TEST(SceneOverrides, PathThroughAValueOfTheWrongTypeInTheFile) {
  json document = completeSceneJson();
  document["calibration"] = 5;
  expectContains(parseError(document, {"calibration.mass=1"}),
                 {"scenes/x.json: --set calibration.mass=1: calibration is not an object in the "
                  "scene (it is 5)"});
  document = completeSceneJson();
  document["fluid"]["blocks"] = "none";
  expectContains(parseError(document, {"fluid.blocks.0.min=[0,0,0]"}),
                 {"fluid.blocks is not an array in the scene (it is \"none\")"});
}

// A bad value from --set gets the message a bad file value gets, plus where it came from.
TEST(SceneOverrides, BadValuesSayWhichOverrideSetThem) {
  EXPECT_EQ(
      parseError(minimalSceneJson(), {"fluid.spacing=-0.01"}),
      "scenes/x.json: fluid.spacing: expected a number in [1e-06, 100], got -0.01 (from --set "
      "fluid.spacing=-0.01)");
  EXPECT_EQ(parseError(minimalSceneJson(), {"output.format=vtk"}),
            "scenes/x.json: output.format: expected one of \"vtp\", \"ply\", \"csv\", \"none\", "
            "got \"vtk\" (from --set output.format=vtk)");
  expectContains(parseError(minimalSceneJson(), {"domain.min.0=abc"}),
                 {"scenes/x.json: domain.min: expected an array of 3 numbers, got "
                  "[\"abc\",0,0] (from --set domain.min.0=abc)"});
  expectContains(parseError(minimalSceneJson(), {"fluid.viscosity={\"modle\":\"muller\"}"}),
                 {"unknown key fluid.viscosity.modle (did you mean fluid.viscosity.model?) "
                  "(from --set fluid.viscosity={\"modle\":\"muller\"})"});
}

TEST(SceneOverrides, CrossChecksNameTheOverridesOfBothKeys) {
  expectContains(parseError(completeSceneJson(), {"fluid.blocks.0.min=[0.5,0,0]"}),
                 {"fluid.blocks[0].max: expected a point above fluid.blocks[0].min",
                  "(from --set fluid.blocks.0.min=[0.5,0,0])"});
  expectContains(parseError(completeSceneJson(), {"domain.max=[1,1.2,0.3]"}),
                 {"fluid.blocks[1].max: expected a point inside the domain box",
                  "(from --set domain.max=[1,1.2,0.3])"});
}

TEST(SceneOverrides, ValuesFromTheFileAreNotBlamedOnOverrides) {
  json document = minimalSceneJson();
  document["time"] = {{"cfl", 2}};
  const std::string message = parseError(document, {"fluid.spacing=0.02"});
  EXPECT_EQ(message, "scenes/x.json: time.cfl: expected a number in (0, 1], got 2");
}

TEST(SceneOverrides, ReplacedOverridesAreNotBlamed) {
  const std::string message = parseError(
      minimalSceneJson(), {"fluid.viscosity.value=-1", "fluid.viscosity={\"value\":-2}"});
  EXPECT_EQ(message,
            "scenes/x.json: fluid.viscosity.value: expected a non-negative number, got -2 (from "
            "--set fluid.viscosity={\"value\":-2})");
}

TEST(SceneOverrides, VectorsAreNotCreatedOneElementAtATime) {
  // Block 1 of the complete scene has no velocity; gravity has three elements.
  EXPECT_EQ(parseError(completeSceneJson(), {"fluid.blocks.1.velocity.0=2"}),
            "scenes/x.json: --set fluid.blocks.1.velocity.0=2: fluid.blocks[1].velocity is not "
            "in the scene, so it has no element 0; set the whole array instead, as in "
            "fluid.blocks.1.velocity=[x,y,z]");
  EXPECT_EQ(
      parseWith(completeSceneJson(), {"fluid.blocks.1.velocity=[2,0,0]"}).fluid.blocks[1].velocity,
      (Vec3d{2, 0, 0}));
}

TEST(SceneOverrides, ApplyOverridesReportsKeyPaths) {
  json document = completeSceneJson();
  const std::vector<AppliedOverride> applied =
      applyOverrides(document, {"fluid.blocks.0.velocity.2=1", "time.cfl=0.5"}, kSource);
  ASSERT_EQ(applied.size(), 2u);
  EXPECT_EQ(applied[0].keyPath, "fluid.blocks[0].velocity[2]");
  EXPECT_EQ(applied[0].text, "fluid.blocks.0.velocity.2=1");
  EXPECT_EQ(applied[1].keyPath, "time.cfl");
  EXPECT_EQ(document["fluid"]["blocks"][0]["velocity"], json::parse("[1,0,1]"));
  EXPECT_EQ(document["time"]["cfl"], 0.5);
}

}  // namespace
}  // namespace sph::scene
