// Tests of src/scene/scene_loader: valid scenes, defaults, files, and the JSON round trip.
// Errors are in scene_errors_test.cpp, overrides in scene_overrides_test.cpp.
#include "scene/scene_loader.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_schema.hpp"
#include "scene_test_support.hpp"
#include "sph/error.hpp"
#include "sph/scene_file.hpp"

namespace sph::scene {
namespace {

using nlohmann::json;
using scene_test::completeSceneJson;
using scene_test::expectScenesEqual;
using scene_test::kSource;
using scene_test::minimalSceneJson;

TEST(SceneLoader, CompleteSceneSetsEveryField) {
  const Scene scene = parseScene(completeSceneJson(), kSource);

  EXPECT_EQ(scene.sourcePath, kSource);
  EXPECT_EQ(scene.name, "dam_break");
  EXPECT_EQ(scene.description, "A column of water collapses.");
  EXPECT_EQ(scene.domain.box.min, (Vec3d{-0.1, 0, -0.2}));
  EXPECT_EQ(scene.domain.box.max, (Vec3d{1.5, 1.2, 0.3}));
  EXPECT_EQ(scene.domain.outside, OutsidePolicy::Clamp);
  EXPECT_TRUE(scene.domain.dampedBox);
  EXPECT_EQ(scene.domain.damping, 0.3);
  EXPECT_EQ(scene.gravity, (Vec3d{0, -3.7, 0.5}));

  const FluidDesc& fluid = scene.fluid;
  EXPECT_EQ(fluid.restDensity, 998.2);
  EXPECT_EQ(fluid.spacing, 0.02);
  EXPECT_EQ(fluid.supportRatio, 2.5);
  EXPECT_EQ(fluid.solver, FluidSolver::Dfsph);
  EXPECT_EQ(fluid.dfsph.densityTolerance, 0.001);
  EXPECT_EQ(fluid.dfsph.divergenceTolerance, 0.002);
  EXPECT_EQ(fluid.dfsph.minIterations, 2);
  EXPECT_EQ(fluid.dfsph.maxIterations, 50);
  EXPECT_FALSE(fluid.dfsph.warmStart);
  EXPECT_EQ(fluid.dfsph.forceFactor, 0.05);
  EXPECT_EQ(fluid.kernel, KernelKind::WendlandC2);
  EXPECT_EQ(fluid.eos, EquationOfState::Tait);
  EXPECT_FALSE(fluid.clampNegativePressure);
  EXPECT_EQ(fluid.pressureForm, PressureForm::Paper);
  EXPECT_EQ(fluid.viscosityModel, ViscosityModel::Muller);
  EXPECT_EQ(fluid.viscosity, 0.05);
  EXPECT_EQ(fluid.wallFriction, 0.4);
  EXPECT_EQ(fluid.surfaceTension, 0.0728);
  EXPECT_EQ(fluid.surfaceThreshold, std::optional<double>(6.5));
  ASSERT_EQ(fluid.blocks.size(), 2u);
  EXPECT_EQ(fluid.blocks[0].box.min, (Vec3d{0, 0, -0.1}));
  EXPECT_EQ(fluid.blocks[0].box.max, (Vec3d{0.4, 0.6, 0.2}));
  EXPECT_EQ(fluid.blocks[0].velocity, (Vec3d{1, 0, -0.25}));
  EXPECT_EQ(fluid.blocks[0].angularVelocity, (Vec3d{0, 2, 0}));
  EXPECT_EQ(fluid.blocks[1].box.min, (Vec3d{1, 0, 0}));
  EXPECT_EQ(fluid.blocks[1].box.max, (Vec3d{1.2, 0.1, 0.1}));
  EXPECT_EQ(fluid.blocks[1].velocity, (Vec3d{0, 0, 0}));

  ASSERT_EQ(scene.walls.size(), 6u);
  EXPECT_EQ(scene.walls[0].kind, WallKind::Tank);
  EXPECT_EQ(scene.walls[0].box.min, (Vec3d{0, 0, -0.15}));
  EXPECT_EQ(scene.walls[0].box.max, (Vec3d{1.4, 1.0, 0.25}));
  EXPECT_EQ(scene.walls[0].layers, 3);
  EXPECT_TRUE(scene.walls[0].closed);
  EXPECT_EQ(scene.walls[0].name, "wall0");
  EXPECT_EQ(scene.walls[1].name, "crate");
  EXPECT_EQ(scene.walls[1].kind, WallKind::Box);
  EXPECT_EQ(scene.walls[1].fluid, FluidSide::Inside);
  EXPECT_EQ(scene.walls[1].layers, 1);
  EXPECT_EQ(scene.walls[2].kind, WallKind::Sphere);
  EXPECT_EQ(scene.walls[2].center, (Vec3d{0.3, 0.5, 0}));
  EXPECT_EQ(scene.walls[2].radius, 0.1);
  EXPECT_EQ(scene.walls[2].layers, 2);
  const WallDesc& pipe = scene.walls[3];
  EXPECT_EQ(pipe.kind, WallKind::Cylinder);
  EXPECT_EQ(pipe.length, 0.3);
  EXPECT_EQ(pipe.axis, (Vec3d{1, 0, 0}));
  EXPECT_FALSE(pipe.capped);
  EXPECT_EQ(pipe.layers, 4);
  const WallDesc& ramp = scene.walls[4];
  EXPECT_EQ(ramp.kind, WallKind::Plane);
  EXPECT_EQ(ramp.corner, (Vec3d{0.8, 0, -0.1}));
  EXPECT_EQ(ramp.edge1, (Vec3d{0.3, 0.2, 0}));
  EXPECT_EQ(ramp.edge2, (Vec3d{0, 0, 0.2}));
  const WallDesc& funnel = scene.walls[5];
  EXPECT_EQ(funnel.kind, WallKind::Mesh);
  EXPECT_EQ(funnel.meshFile, "meshes/funnel.obj");
  EXPECT_EQ(funnel.center, (Vec3d{0.5, 0.8, 0}));
  EXPECT_EQ(funnel.scale, 0.5);
  EXPECT_TRUE(funnel.open);

  ASSERT_EQ(scene.objects.size(), 1u);
  const DeformableDesc& vessel = scene.objects[0].deformable;
  EXPECT_EQ(vessel.stiffness, 30.0);
  EXPECT_EQ(vessel.damping, 0.002);
  EXPECT_EQ(vessel.breakingStrain, 0.3);
  EXPECT_EQ(vessel.springReach, 2.2);
  ASSERT_EQ(vessel.pinned.size(), 1u);
  EXPECT_EQ(vessel.pinned[0].max, (Vec3d{0.31, 0.4, 0.1}));
  ASSERT_EQ(vessel.cuts.size(), 1u);
  EXPECT_EQ(vessel.cuts[0].min, (Vec3d{0.5, 0.2, -0.01}));
  EXPECT_EQ(vessel.model, DeformableModel::Xpbd);
  EXPECT_EQ(vessel.substeps, 12);
  EXPECT_EQ(vessel.bendingStiffness, 5.0);

  EXPECT_EQ(scene.calibration.mass, 0.008);
  EXPECT_EQ(scene.calibration.maxExpectedSpeed, 3.5);
  EXPECT_EQ(scene.calibration.speedOfSound, 35.0);
  EXPECT_EQ(scene.calibration.stiffness, 1.75e5);

  EXPECT_EQ(scene.time.duration, 2.5);
  EXPECT_EQ(scene.time.cfl, 0.3);
  EXPECT_EQ(scene.time.forceFactor, 0.2);
  EXPECT_EQ(scene.time.viscousFactor, 0.1);
  EXPECT_EQ(scene.time.maxDt, 0.005);
  EXPECT_EQ(scene.time.fixedDt, 0.0001);

  EXPECT_EQ(scene.output.fps, 60.0);
  EXPECT_EQ(scene.output.format, FrameFormat::Ply);
  EXPECT_EQ(scene.output.probeRate, 250.0);
  ASSERT_EQ(scene.probes.size(), 4u);
  EXPECT_EQ(scene.probes[0].name, "sensor");
  EXPECT_EQ(scene.probes[0].kind, ProbeKind::Point);
  EXPECT_EQ(scene.probes[0].position, (Vec3d{1.4, 0.05, 0}));
  EXPECT_EQ(scene.probes[1].kind, ProbeKind::Level);
  EXPECT_EQ(scene.probes[1].from, (Vec3d{0.5, 0, 0}));
  EXPECT_EQ(scene.probes[1].to, (Vec3d{0.5, 1, 0}));
  EXPECT_EQ(scene.probes[2].kind, ProbeKind::Force);
  EXPECT_EQ(scene.probes[2].object, "vessel");
  EXPECT_EQ(scene.probes[3].wall, "crate");
  EXPECT_EQ(scene.probes[3].object, "");
  EXPECT_EQ(scene.failure.maxDensityError, 0.2);
  EXPECT_EQ(scene.limits.maxParticles, 2e6);
  EXPECT_EQ(scene.limits.maxMemoryGb, 4.0);
}

TEST(SceneLoader, AbsentKeysTakeTheDefaultsOfSceneHpp) {
  const Scene scene = parseScene(minimalSceneJson(), kSource);

  // Everything but the required keys, the source and the block is a default.
  Scene expected;
  expected.sourcePath = kSource;
  expected.domain.box = {{0, 0, 0}, {1, 1, 1}};
  FluidBlock block;
  block.box = {{0, 0, 0}, {0.5, 0.5, 0.5}};
  expected.fluid.blocks = {block};
  expectScenesEqual(scene, expected);
  EXPECT_EQ(scene.sourcePath, kSource);

  // A few defaults spelled out, so that a change to scene.hpp is seen here.
  EXPECT_EQ(scene.fluid.spacing, 0.01);
  EXPECT_EQ(scene.fluid.kernel, KernelKind::Muller);
  EXPECT_EQ(scene.fluid.solver, FluidSolver::Wcsph);
  EXPECT_EQ(scene.fluid.dfsph.densityTolerance, 0.0005);
  EXPECT_EQ(scene.gravity, (Vec3d{0, -9.81, 0}));
  EXPECT_TRUE(scene.walls.empty());
  EXPECT_FALSE(scene.calibration.speedOfSound.has_value());
  EXPECT_FALSE(scene.time.fixedDt.has_value());
  EXPECT_EQ(scene.output.format, FrameFormat::Vtp);
  EXPECT_EQ(scene.output.probeRate, 1000.0);
  EXPECT_TRUE(scene.probes.empty());
}

TEST(SceneLoader, DeformablesDefaultToTheSpringModel) {
  json document = minimalSceneJson();
  document["objects"] = json::parse(R"([{"motion": "deformable",
                                          "shape": {"type": "sphere", "radius": 0.1}}])");
  const DeformableDesc d = parseScene(document, kSource).objects.at(0).deformable;
  EXPECT_EQ(d.model, DeformableModel::Springs);  // existing scenes run as before
  EXPECT_EQ(d.substeps, 8);
  EXPECT_EQ(d.bendingStiffness, 0.0);
}

TEST(SceneLoader, NullOptionalValuesAreUnset) {
  json document = completeSceneJson();
  document["calibration"]["mass"] = nullptr;
  document["time"]["fixed_dt"] = nullptr;
  const Scene scene = parseScene(document, kSource);
  EXPECT_FALSE(scene.calibration.mass.has_value());
  EXPECT_FALSE(scene.time.fixedDt.has_value());
  EXPECT_EQ(scene.calibration.stiffness, 1.75e5);
}

TEST(SceneLoader, WallLayersWrittenAsWholeFloatAreAccepted) {
  json document = completeSceneJson();
  document["walls"][0]["layers"] = 4.0;
  EXPECT_EQ(parseScene(document, kSource).walls[0].layers, 4);
}

TEST(SceneLoader, BoxesMayTouchTheDomainFaces) {
  json document = minimalSceneJson();
  document["fluid"]["blocks"][0]["max"] = {1, 1, 1};
  document["walls"] = json::parse(R"([{"min": [0, 0, 0], "max": [1, 1, 1]}])");
  EXPECT_NO_THROW(parseScene(document, kSource));
}

// The complete scene has objects, which a periodic domain refuses: its periodic axes are read
// and written here.
TEST(SceneJson, RoundTripsPeriodicAxes) {
  json document = minimalSceneJson();
  document["domain"]["periodic"] = "zx";
  const Scene original = parseScene(document, kSource);
  EXPECT_EQ(original.domain.periodic, (std::array<bool, 3>{true, false, true}));
  const json written = sceneToJson(original);
  EXPECT_EQ(written["domain"]["periodic"], "xz");
  expectScenesEqual(parseScene(written, kSource), original);
  EXPECT_EQ(sceneToJson(parseScene(minimalSceneJson(), kSource))["domain"]["periodic"], "");
}

// The installed reader (sph/scene_file.hpp) takes and gives text, not JSON types.
TEST(PublicSceneFile, TextRoundTripsAndErrorsNameTheSource) {
  const Scene original = sph::parseScene(completeSceneJson().dump(), kSource);
  expectScenesEqual(sph::parseScene(sph::sceneToJsonText(original), kSource), original);
  const Scene overridden =
      sph::parseScene(minimalSceneJson().dump(), kSource, {"fluid.spacing=0.02"});
  EXPECT_EQ(overridden.fluid.spacing, 0.02);
  try {
    sph::parseScene("{\"domain\": ", "from_python");
    FAIL() << "accepted JSON cut short";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("from_python: invalid JSON", 0), 0u) << e.what();
  }
  json negative = minimalSceneJson();
  negative["fluid"]["spacing"] = -1;
  try {
    sph::parseScene(negative.dump(), "from_python");
    FAIL() << "accepted a negative spacing";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("from_python: fluid.spacing: expected", 0), 0u)
        << e.what();
  }
}

TEST(SceneJson, RoundTripsTheCompleteScene) {
  const Scene original = parseScene(completeSceneJson(), kSource);
  const json written = sceneToJson(original);
  const Scene reread = parseScene(written, kSource);
  expectScenesEqual(reread, original);
  EXPECT_EQ(sceneToJson(reread), written);
}

TEST(SceneJson, RoundTripsDefaultsAndUnsetOptionals) {
  const Scene original = parseScene(minimalSceneJson(), kSource);
  const json written = sceneToJson(original);
  EXPECT_TRUE(written["calibration"]["mass"].is_null());
  EXPECT_TRUE(written["calibration"]["speed_of_sound"].is_null());
  EXPECT_TRUE(written["time"]["fixed_dt"].is_null());
  EXPECT_EQ(written["fluid"]["kernel"], "muller");
  EXPECT_EQ(written["walls"], json::array());
  expectScenesEqual(parseScene(written, kSource), original);
}

TEST(SceneJson, RoundTripsValuesThatNeedEveryDigit) {
  Scene original = parseScene(minimalSceneJson(), kSource);
  original.fluid.spacing = 0.1 + 0.2;  // 0.30000000000000004
  original.time.duration = 1.0 / 3.0;
  original.gravity = {1e-300, -9.80665, 1e4 / 3.0};
  expectScenesEqual(parseScene(sceneToJson(original), kSource), original);
}

// Every key of the schema is written, in every object and every array element; a wall, a probe
// and an emitter, which read only the keys of their type, with those.
void expectEveryKey(const json& value, const KeySchema& schema, const std::string& path) {
  if (schema.shape == KeySchema::Shape::Object && path.rfind("walls[", 0) == 0) {
    ASSERT_TRUE(value.is_object() && value.contains("type")) << path;
    const std::map<std::string, std::vector<std::string>> byType{
        {"tank", {"min", "max", "closed"}},
        {"box", {"min", "max", "fluid"}},
        {"sphere", {"center", "radius", "fluid"}},
        {"cylinder", {"center", "radius", "length", "axis", "capped", "fluid"}},
        {"plane", {"corner", "edge1", "edge2"}},
        {"mesh", {"file", "center", "scale", "open"}}};
    std::vector<std::string> keys = byType.at(value["type"].get<std::string>());
    keys.insert(keys.end(), {"name", "type", "layers"});
    for (const std::string& key : keys)
      EXPECT_TRUE(value.contains(key)) << joinKey(path, key) << " is not written";
    EXPECT_EQ(value.size(), keys.size()) << path << " has keys of another type of wall";
  } else if (schema.shape == KeySchema::Shape::Object && path.rfind("emitters[", 0) == 0) {
    ASSERT_TRUE(value.is_object() && value.contains("shape")) << path;
    std::vector<std::string> keys{"name", "shape", "speed", "start", "end"};
    if (value["shape"] == "disc")
      keys.insert(keys.end(), {"center", "radius", "direction"});
    else
      keys.insert(keys.end(), {"corner", "edge1", "edge2"});
    for (const std::string& key : keys)
      EXPECT_TRUE(value.contains(key)) << joinKey(path, key) << " is not written";
    EXPECT_EQ(value.size(), keys.size()) << path << " has keys of the other shape";
  } else if (schema.shape == KeySchema::Shape::Object && path.rfind("probes[", 0) == 0) {
    ASSERT_TRUE(value.is_object() && value.contains("type")) << path;
    const std::map<std::string, std::vector<std::string>> byType{
        {"point", {"position"}}, {"level", {"from", "to"}}, {"force", {"object", "wall"}}};
    std::vector<std::string> keys = byType.at(value["type"].get<std::string>());
    keys.insert(keys.end(), {"name", "type"});
    for (const std::string& key : keys)
      EXPECT_TRUE(value.contains(key)) << joinKey(path, key) << " is not written";
    EXPECT_EQ(value.size(), keys.size()) << path << " has keys of another type of probe";
  } else if (schema.shape == KeySchema::Shape::Object) {
    ASSERT_TRUE(value.is_object()) << path;
    for (const KeySchema& key : schema.children) {
      ASSERT_TRUE(value.contains(key.name)) << joinKey(path, key.name) << " is not written";
      expectEveryKey(value[key.name], key, joinKey(path, key.name));
    }
    EXPECT_EQ(value.size(), schema.children.size()) << path << " has keys outside the schema";
  } else if (schema.shape == KeySchema::Shape::Array) {
    ASSERT_TRUE(value.is_array()) << path;
    for (std::size_t i = 0; i < value.size(); ++i) {
      expectEveryKey(value[i], schema.element(), joinIndex(path, i));
    }
  }
}

TEST(SceneJson, WritesEveryKeyOfTheSchema) {
  expectEveryKey(sceneToJson(parseScene(completeSceneJson(), kSource)), sceneSchema(), "");
  expectEveryKey(sceneToJson(parseScene(minimalSceneJson(), kSource)), sceneSchema(), "");
}

class SceneFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("sph_scene_loader_test_" + std::string(info->name()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& text) {
    const std::filesystem::path file = dir_ / name;
    std::ofstream(file) << text;
    return file;
  }

  std::string loadError(const std::filesystem::path& file,
                        const std::vector<std::string>& overrides = {}) {
    try {
      loadScene(file, overrides);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "loadScene accepted " << file;
    return "";
  }

  std::filesystem::path dir_;
};

TEST_F(SceneFile, LoadsAFileAndAppliesOverrides) {
  const auto file = write("dam.json", completeSceneJson().dump(2));
  const Scene scene = loadScene(file, {"fluid.spacing=0.03"});
  EXPECT_EQ(scene.sourcePath, file.string());
  EXPECT_EQ(scene.name, "dam_break");
  EXPECT_EQ(scene.fluid.spacing, 0.03);
}

TEST_F(SceneFile, MissingFileNamesThePath) {
  const auto file = dir_ / "nothing.json";
  const std::string message = loadError(file);
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
}

TEST_F(SceneFile, DirectoryIsNotAScene) {
  const std::string message = loadError(dir_);
  EXPECT_NE(message.find(dir_.string()), std::string::npos) << message;
  EXPECT_NE(message.find("directory"), std::string::npos) << message;
}

TEST_F(SceneFile, InvalidJsonGivesLineAndColumn) {
  const auto file = write("broken.json", "{\n  \"name\": \"x\",\n  \"domain\": {,\n}\n");
  const std::string message = loadError(file);
  EXPECT_EQ(message.rfind(file.string() + ": invalid JSON: ", 0), 0u) << message;
  EXPECT_NE(message.find("line 3, column 14"), std::string::npos) << message;
  EXPECT_EQ(message.find("[json.exception"), std::string::npos) << message;
}

TEST_F(SceneFile, EmptyFileIsInvalidJson) {
  const auto file = write("empty.json", "");
  const std::string message = loadError(file);
  EXPECT_NE(message.find(file.string() + ": invalid JSON"), std::string::npos) << message;
}

TEST_F(SceneFile, NumberTooLargeForADouble) {
  const auto file = write("huge.json", R"({"time": {"duration": 1e999}})");
  const std::string message = loadError(file);
  EXPECT_EQ(message.rfind(file.string() + ": invalid JSON: ", 0), 0u) << message;
  EXPECT_NE(message.find("1e999"), std::string::npos) << message;
}

// JSON nested 60,000 deep once overflowed the stack while the loader copied and printed it.
TEST_F(SceneFile, NestingNoSceneNeedsIsRefusedWithoutRecursing) {
  const std::string deep = std::string(60000, '[') + std::string(60000, ']');
  const auto file = write("deep.json", R"({"name": "x", "description": )" + deep + "}");
  EXPECT_EQ(loadError(file), file.string() +
                                 ": JSON nested deeper than 32 levels; no scene needs more than "
                                 "a few");
  // Also through --set, and in a document built elsewhere.
  const auto fine = write("fine.json", minimalSceneJson().dump());
  EXPECT_EQ(loadError(fine, {"description=" + deep}),
            fine.string() + ": --set description=" + std::string(65, '[') +
                "...: JSON nested deeper than 32 levels; no scene needs more than a few");
  json document = minimalSceneJson();
  document["description"] = json::parse(std::string(100, '[') + std::string(100, ']'));
  EXPECT_EQ(scene_test::parseError(document),
            "scenes/x.json: JSON nested deeper than 32 levels; no scene needs more than a few");
}

// The last of two values used to win silently.
TEST_F(SceneFile, AKeyGivenTwiceIsAnError) {
  const auto file = write("twice.json", R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1]},
    "fluid": {"spacing": 0.01, "blocks": [{"min": [0, 0, 0], "max": [1, 1, 1]},
                                          {"min": [0, 0, 0], "max": [1, 1, 1], "min": [0, 0, 0]}],
              "spacing": 0.02}})");
  EXPECT_EQ(loadError(file),
            file.string() + ": fluid.blocks[1].min: the key appears twice in one object");
  const auto fine = write("fine.json", minimalSceneJson().dump());
  EXPECT_EQ(loadError(fine, {R"(gravity={"a": 1, "a": 2})"}),
            fine.string() +
                R"(: --set gravity={"a": 1, "a": 2}: a: the key appears twice in one object)");
}

TEST_F(SceneFile, ValidationErrorsNameTheFile) {
  json document = minimalSceneJson();
  document["fluid"]["spacing"] = -0.01;
  const auto file = write("bad.json", document.dump());
  EXPECT_EQ(loadError(file),
            file.string() + ": fluid.spacing: expected a number in [1e-06, 100], got -0.01");
}

}  // namespace
}  // namespace sph::scene
