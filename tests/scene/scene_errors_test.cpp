// Tests of the messages src/scene/scene_loader gives for bad scenes: each names the file, the
// dotted key and what was expected.
#include <limits>
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
using scene_test::minimalSceneJson;
using scene_test::parseError;

// `document` with the value at a JSON pointer (`/fluid/spacing`) replaced.
json with(json document, const std::string& pointer, json value) {
  document[json::json_pointer(pointer)] = std::move(value);
  return document;
}

json without(json document, const std::string& pointer) {
  const json::json_pointer p(pointer);
  document[p.parent_pointer()].erase(p.back());
  return document;
}

void expectContains(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}

TEST(SceneErrors, NegativeSpacing) {
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/fluid/spacing", -0.01)),
            "scenes/x.json: fluid.spacing: expected a number in [1e-06, 100], got -0.01");
}

TEST(SceneErrors, UnknownKernelListsTheChoices) {
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/fluid/kernel", "poly6")),
            "scenes/x.json: fluid.kernel: expected one of \"muller\", \"cubic_spline\", "
            "\"wendland_c2\", got \"poly6\"");
}

TEST(SceneErrors, VectorThatIsNotThreeNumbers) {
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/domain/min", "abc")),
            "scenes/x.json: domain.min: expected an array of 3 numbers, got \"abc\"");
  expectContains(parseError(with(minimalSceneJson(), "/gravity", {0, -9.81})),
                 {"scenes/x.json", "gravity: expected an array of 3 numbers, got [0,-9.81]"});
  expectContains(parseError(with(minimalSceneJson(), "/fluid/blocks/0/velocity", {1, "2", 3})),
                 {"fluid.blocks[0].velocity: expected an array of 3 numbers"});
}

TEST(SceneErrors, MissingRequiredKeys) {
  EXPECT_EQ(parseError(without(minimalSceneJson(), "/domain/max")),
            "scenes/x.json: domain.max: required key is missing");
  EXPECT_EQ(parseError(without(minimalSceneJson(), "/domain")),
            "scenes/x.json: domain: required key is missing");
  EXPECT_EQ(parseError(without(minimalSceneJson(), "/fluid/blocks")),
            "scenes/x.json: fluid.blocks: required key is missing");
  EXPECT_EQ(parseError(without(minimalSceneJson(), "/fluid/blocks/0/min")),
            "scenes/x.json: fluid.blocks[0].min: required key is missing");
  const json wall = json::parse(R"({"min": [0, 0, 0]})");
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/walls", {wall})),
            "scenes/x.json: walls[0].max: required key is missing");
}

TEST(SceneErrors, NoFluidBlocks) {
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/fluid/blocks", json::array())),
            "scenes/x.json: fluid.blocks: expected a non-empty array of objects, got []");
  expectContains(parseError(with(minimalSceneJson(), "/fluid/blocks/0", 3)),
                 {"scenes/x.json: fluid.blocks[0]: expected an object, got 3"});
  expectContains(parseError(with(minimalSceneJson(), "/walls", json::object())),
                 {"scenes/x.json: walls: expected an array of objects, got {}"});
}

TEST(SceneErrors, SectionThatIsNotAnObject) {
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/time", 5)),
            "scenes/x.json: time: expected an object, got 5");
  EXPECT_EQ(parseError(json::array({1, 2})),
            "scenes/x.json: expected a JSON object at the top level, got [1,2]");
}

// Each key with a bad value: the message gives the dotted key and the expectation.
TEST(SceneErrors, ValuesOutOfRange) {
  struct Case {
    const char* pointer;
    json value;
    const char* expected;  // after "scenes/x.json: "
  };
  const Case cases[] = {
      {"/name", 3, "name: expected a string, got 3"},
      {"/domain/outside", "wrap", "domain.outside: expected one of \"remove\", \"clamp\""},
      {"/domain/damped_box", "yes", "domain.damped_box: expected true or false, got \"yes\""},
      {"/domain/damping", 1.5, "domain.damping: expected a number in [0, 1], got 1.5"},
      {"/fluid/rest_density", 0, "fluid.rest_density: expected a number in [0.001, 100000], got 0"},
      {"/fluid/support_ratio", 5, "fluid.support_ratio: expected a number in [1, 4], got 5"},
      {"/fluid/support_ratio", 0.5, "fluid.support_ratio: expected a number in [1, 4], got 0.5"},
      {"/fluid/eos", "ideal_gas", "fluid.eos: expected one of \"linear\", \"ratio\", \"tait\""},
      {"/fluid/clamp_negative_pressure", 1, "fluid.clamp_negative_pressure: expected true or"},
      {"/fluid/pressure_form", "x", "fluid.pressure_form: expected one of \"paper\", \"symm"},
      {"/fluid/solver", "pcisph", "fluid.solver: expected one of \"wcsph\", \"dfsph\""},
      {"/fluid/dfsph/density_tolerance", 0,
       "fluid.dfsph.density_tolerance: expected a number in (0, 1)"},
      {"/fluid/dfsph/max_iterations", 1,
       "fluid.dfsph.max_iterations: expected an integer in [2, 10000]"},
      {"/fluid/dfsph/force_factor", 2, "fluid.dfsph.force_factor: expected a number in (0, 1]"},
      {"/fluid/dfsph/chebyshev", 0.8, "fluid.dfsph.chebyshev: removed from sph: Chebyshev's"},
      {"/fluid/viscosity/model", "xsph", "fluid.viscosity.model: expected one of \"muller\""},
      {"/fluid/viscosity/value", -1, "fluid.viscosity.value: expected a non-negative number"},
      {"/fluid/viscosity/wall_friction", "a lot", "fluid.viscosity.wall_friction: expected a"},
      {"/fluid/surface_tension/coefficient", -0.07, "fluid.surface_tension.coefficient: exp"},
      {"/fluid/surface_tension/threshold", 0, "fluid.surface_tension.threshold: expected a pos"},
      {"/fluid/spacing", nullptr, "fluid.spacing: expected a number in [1e-06, 100], got null"},
      {"/walls/0/type", "bowl",
       "walls[0].type: expected one of \"tank\", \"box\", \"sphere\", \"cylinder\", \"plane\", "
       "\"mesh\", got \"bowl\""},
      {"/walls/1/fluid", "above", "walls[1].fluid: expected one of \"outside\", \"inside\""},
      {"/walls/0/layers", 5, "walls[0].layers: expected an integer in [1, 4], got 5"},
      {"/walls/0/layers", 2.5, "walls[0].layers: expected an integer in [1, 4], got 2.5"},
      {"/walls/0/closed", "no", "walls[0].closed: expected true or false"},
      {"/objects/0/deformable/model", "fem",
       "objects[0].deformable.model: expected one of \"springs\", \"xpbd\", got \"fem\""},
      {"/objects/0/deformable/spring_reach", 1,
       "objects[0].deformable.spring_reach: expected a number in (1, 3], got 1"},
      {"/objects/0/deformable/substeps", 0,
       "objects[0].deformable.substeps: expected an integer in [1, 1000], got 0"},
      {"/objects/0/deformable/substeps", 2.5,
       "objects[0].deformable.substeps: expected an integer in [1, 1000], got 2.5"},
      {"/objects/0/deformable/bending_stiffness", -1,
       "objects[0].deformable.bending_stiffness: expected a non-negative number, got -1"},
      {"/interaction/coupling", "glue",
       "interaction.coupling: expected one of \"contact\", \"boundary\", got \"glue\""},
      {"/calibration/mass", -1, "calibration.mass: expected a positive number or null, got -1"},
      {"/calibration/max_expected_speed", 0,
       "calibration.max_expected_speed: expected a number in (0, 10000] or null, got 0"},
      {"/calibration/speed_of_sound", "fast",
       "calibration.speed_of_sound: expected a number in (0, 100000] or null"},
      {"/calibration/stiffness", false, "calibration.stiffness: expected a positive number or"},
      {"/time/duration", -2, "time.duration: expected a number in (0, 1000000], got -2"},
      {"/time/cfl", 0, "time.cfl: expected a number in (0, 1], got 0"},
      {"/time/force_factor", 1.01, "time.force_factor: expected a number in (0, 1], got 1.01"},
      {"/time/viscous_factor", 2, "time.viscous_factor: expected a number in (0, 1]"},
      {"/time/max_dt", 0, "time.max_dt: expected a number in [1e-09, 10], got 0"},
      {"/time/fixed_dt", -1e-4, "time.fixed_dt: expected a number in [1e-09, 10] or null"},
      {"/output/fps", 0, "output.fps: expected a number in (0, 100000], got 0"},
      // A name is the output folder under out/; this one once wrote outside it.
      {"/name", "../../escaped_run",
       "name: expected a name without '/' or '\\' that is not '.' or '..', got "
       "\"../../escaped_run\""},
      {"/name", "..", "name: expected a name without '/'"},
      // Values that validate once accepted and run then hung on or crashed with.
      {"/fluid/spacing", 1e-300, "fluid.spacing: expected a number in [1e-06, 100], got 1e-300"},
      {"/fluid/spacing", 1e-21, "fluid.spacing: expected a number in [1e-06, 100], got 1e-21"},
      {"/time/fixed_dt", 1e-300, "time.fixed_dt: expected a number in [1e-09, 10] or null"},
      {"/output/fps", 1e9, "output.fps: expected a number in (0, 100000], got 1000000000"},
      {"/objects/0/spacing", 1e-300,
       "objects[0].spacing: expected 0 (the fluid's) or a number in [1e-06, 100], got 1e-300"},
      {"/output/format", "vtk",
       "output.format: expected one of \"vtp\", \"ply\", \"csv\", "
       "\"none\", got \"vtk\""},
      {"/failure/max_density_error", -0.1, "failure.max_density_error: expected a positive"},
      {"/failure/max_speed", 0, "failure.max_speed: expected a number in (0, 10000] or null"},
      {"/limits/max_particles", -1, "limits.max_particles: expected a non-negative number"},
      {"/render/look", "spheres", "render.look: expected one of \"liquid\", \"particles\""},
      {"/render/colour", json::array({1.0, 0.5, 2.0}),
       "render.colour: expected 3 numbers from 0 to 1, got [1.0,0.5,2.0]"},
      {"/render/absorption", json::array({-1.0, 0.0, 0.0}),
       "render.absorption: expected 3 numbers from 0 to 1000000, got [-1.0,0.0,0.0]"},
      // Values past any physical scene, that once failed at step 0 (exit 3) or hung.
      {"/fluid/rest_density", 1e300, "fluid.rest_density: expected a number in [0.001, 100000]"},
      {"/gravity", json::array({0, -1e308, 0}),
       "gravity: expected 3 numbers within ±10000, got [0,-1e+308,0]"},
      {"/fluid/blocks/0/velocity", json::array({1e30, 0, 0}),
       "fluid.blocks[0].velocity: expected 3 numbers within ±10000"},
      {"/objects/0/velocity", json::array({0, 0, 1e5}),
       "objects[0].velocity: expected 3 numbers within ±10000"},
      {"/objects/0/density", 0, "objects[0].density: expected a number in [0.001, 100000]"},
      {"/objects/0/shape/radius", 1e6, "objects[0].shape.radius: expected a number in [0, 10000]"},
      {"/domain/max", json::array({1e7, 1, 1}), "domain.max: expected 3 numbers within ±1000000"},
      {"/emitters/0/speed", 1e5, "emitters[0].speed: expected a number in (0, 10000]"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.pointer);
    const std::string message = parseError(with(completeSceneJson(), c.pointer, c.value));
    EXPECT_EQ(message.rfind(std::string("scenes/x.json: ") + c.expected, 0), 0u) << message;
  }
}

// JSON text cannot hold infinities, but a document built in code can.
TEST(SceneErrors, NumbersMustBeFinite) {
  const double inf = std::numeric_limits<double>::infinity();
  expectContains(parseError(with(minimalSceneJson(), "/domain/max", {1, 1, inf})),
                 {"scenes/x.json: domain.max: expected an array of 3 numbers"});
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/time/duration", inf)),
            "scenes/x.json: time.duration: expected a number in (0, 1000000], got inf");
}

TEST(SceneErrors, UnknownKeySuggestsTheNearestKey) {
  json document = minimalSceneJson();
  document["fluid"]["viscosty"] = {{"value", 0.1}};
  EXPECT_EQ(parseError(document),
            "scenes/x.json: unknown key fluid.viscosty (did you mean fluid.viscosity?)");

  EXPECT_EQ(parseError(with(minimalSceneJson(), "/domain/dampd_box", true)),
            "scenes/x.json: unknown key domain.dampd_box (did you mean domain.damped_box?)");
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/gravty", {0, -1, 0})),
            "scenes/x.json: unknown key gravty (did you mean gravity?)");
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/fluid/blocks/0/velocty", {0, 0, 0})),
            "scenes/x.json: unknown key fluid.blocks[0].velocty (did you mean "
            "fluid.blocks[0].velocity?)");
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/time/fixed_td", 0.1)),
            "scenes/x.json: unknown key time.fixed_td (did you mean time.fixed_dt?)");
}

TEST(SceneErrors, UnknownKeyFarFromAnyListsTheKnownKeys) {
  const std::string message = parseError(with(minimalSceneJson(), "/output/colour", "red"));
  EXPECT_EQ(
      message,
      "scenes/x.json: unknown key output.colour (keys of output are: fps, format, probe_rate)");
  const std::string top = parseError(with(minimalSceneJson(), "/solver", "pcisph"));
  expectContains(top, {"unknown key solver (top-level keys are: name, description, domain"});
  EXPECT_EQ(top.find("did you mean"), std::string::npos) << top;
}

TEST(SceneErrors, BoxesNeedMinBelowMax) {
  EXPECT_EQ(parseError(with(minimalSceneJson(), "/domain/max", {1, 0, 1})),
            "scenes/x.json: domain.max: expected a point above domain.min [0, 0, 0] on every "
            "axis, got [1, 0, 1]");
  expectContains(
      parseError(with(completeSceneJson(), "/fluid/blocks/1/min", {1.2, 0, 0})),
      {"scenes/x.json: fluid.blocks[1].max: expected a point above fluid.blocks[1].min"});
  expectContains(parseError(with(completeSceneJson(), "/walls/0/max", {1.4, 1.0, -0.2})),
                 {"scenes/x.json: walls[0].max: expected a point above walls[0].min"});
}

TEST(SceneErrors, BoxesMustLieInsideTheDomain) {
  EXPECT_EQ(parseError(with(completeSceneJson(), "/fluid/blocks/1/max", {1.2, 0.1, 0.4})),
            "scenes/x.json: fluid.blocks[1].max: expected a point inside the domain box "
            "[-0.1, 0, -0.2] to [1.5, 1.2, 0.3], got [1.2, 0.1, 0.4]");
  expectContains(parseError(with(completeSceneJson(), "/walls/0/min", {-0.5, 0, 0})),
                 {"scenes/x.json: walls[0].min: expected a point inside the domain box"});
}

TEST(SceneErrors, BadWallsNameTheKey) {
  // Each type reads its own keys; another type's key is refused, not ignored.
  EXPECT_EQ(parseError(with(completeSceneJson(), "/walls/2/min", {0, 0, 0})),
            "scenes/x.json: walls[2].min: not a key of a sphere wall; its keys are name, type, "
            "layers, center, radius, fluid");
  EXPECT_EQ(parseError(without(completeSceneJson(), "/walls/2/radius")),
            "scenes/x.json: walls[2].radius: required key is missing (a length in m)");
  expectContains(parseError(with(completeSceneJson(), "/walls/3/radius", 0.001)),
                 {"scenes/x.json: walls[3].radius: expected at least the fluid's spacing"});
  expectContains(parseError(with(completeSceneJson(), "/walls/3/axis", {0, 0, 0})),
                 {"scenes/x.json: walls[3].axis: expected a direction, got [0, 0, 0]"});
  expectContains(parseError(with(completeSceneJson(), "/walls/4/edge2", {0.6, 0.4, 0})),
                 {"scenes/x.json: walls[4].edge2: expected an edge not parallel to "
                  "walls[4].edge1 [0.3, 0.2, 0], got [0.6, 0.4, 0]"});
  expectContains(parseError(with(completeSceneJson(), "/walls/2/center", {3, 0, 0})),
                 {"scenes/x.json: walls[2].center: expected a point inside the domain box"});
  EXPECT_EQ(parseError(with(completeSceneJson(), "/walls/2/name", "crate")),
            "scenes/x.json: walls[2].name: expected a name no other wall has, got \"crate\" "
            "(also walls[1])");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/probes/3/wall", "lid")),
            "scenes/x.json: probes[3].wall: expected the name of a wall (wall0, crate, wall2, "
            "wall3, wall4, wall5), got \"lid\"");
  expectContains(parseError(with(completeSceneJson(), "/probes/3/object", "vessel")),
                 {"scenes/x.json: probes[3].wall: expected an object or a wall, not both"});
  EXPECT_EQ(parseError(without(completeSceneJson(), "/walls/5/file")),
            "scenes/x.json: walls[5].file: expected the path of an OBJ or STL file");
}

// Periodic axes: letters x, y, z once each; a period of three support radii or more, and a
// whole number of spacings; no objects.
TEST(SceneErrors, BadPeriodicAxesNameTheKey) {
  const json minimal = minimalSceneJson();  // spacing 0.01, support 0.02, domain 1 m
  EXPECT_EQ(parseError(with(minimal, "/domain/periodic", "xw")),
            "scenes/x.json: domain.periodic: expected the periodic axes as letters x, y and z, "
            "each at most once (\"xz\"; \"\" for none), got \"xw\"");
  expectContains(parseError(with(minimal, "/domain/periodic", "yy")), {"got \"yy\""});
  const json narrow = with(with(minimal, "/domain/max/0", 0.05), "/fluid/blocks/0/max/0", 0.05);
  expectContains(parseError(with(narrow, "/domain/periodic", "x")),
                 {"scenes/x.json: domain.periodic: expected the domain to be at least 3 support "
                  "radii (0.06 m) long along periodic axis x, got 0.05 m"});
  expectContains(
      parseError(with(with(minimal, "/domain/periodic", "z"), "/domain/max/2", 0.995)),
      {"scenes/x.json: domain.periodic: expected the domain's length along periodic axis z to "
       "be a whole number of fluid.spacing (0.01 m), got 0.995 m, 99.5 spacings"});
  // The built-in engine carries objects across a periodic face; Bullet's bodies are not.
  const json periodicObjects = with(completeSceneJson(), "/domain/periodic", "y");
  expectContains(parseError(with(periodicObjects, "/object_engine/type", "bullet")),
                 {"scenes/x.json: domain.periodic: expected no periodic axes with "
                  "object_engine.type \"bullet\""});
}

// Boundary coupling hands the objects an incompressible solver's pressure: none without it.
TEST(SceneErrors, BoundaryCouplingNeedsAnIncompressibleSolver) {
  EXPECT_EQ(parseError(with(completeSceneJson(), "/fluid/solver", "wcsph")),
            "scenes/x.json: interaction.coupling: expected \"contact\" with fluid.solver "
            "\"wcsph\" (\"boundary\" needs fluid.solver \"dfsph\" or \"pbf\"), got "
            "\"boundary\"");
}

// Probes head probes.csv's columns by name, read inside the domain, and a force probe needs an
// object.
TEST(SceneErrors, BadProbesNameTheKey) {
  EXPECT_EQ(parseError(with(completeSceneJson(), "/probes/0/type", "gauge")),
            "scenes/x.json: probes[0].type: expected one of \"point\", \"level\", \"force\", "
            "got \"gauge\"");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/probes/0/position", {2.0, 0.05, 0})),
            "scenes/x.json: probes[0].position: expected a point inside the domain box "
            "[-0.1, 0, -0.2] to [1.5, 1.2, 0.3], got [2, 0.05, 0]");
  EXPECT_EQ(parseError(without(completeSceneJson(), "/probes/0/position")),
            "scenes/x.json: probes[0].position: required key is missing");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/probes/1/to", {0.5, 0, 0})),
            "scenes/x.json: probes[1].to: expected a point apart from probes[1].from [0.5, 0, 0], "
            "got the same point");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/probes/2/object", "clamp")),
            "scenes/x.json: probes[2].object: expected the name of an object (vessel), got "
            "\"clamp\"");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/probes/1/name", "sensor")),
            "scenes/x.json: probes[1].name: expected a name no other probe has, got \"sensor\" "
            "(also probes[0])");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/probes/0/name", "a,b")),
            "scenes/x.json: probes[0].name: expected a name without commas or quotes, got "
            "\"a,b\"");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/output/probe_rate", 0)),
            "scenes/x.json: output.probe_rate: expected a number in (0, 10000000], got 0");
}

TEST(SceneErrors, ContinuityDensityNeedsTheWeaklyCompressibleSymmetricSolver) {
  json dfsph = with(completeSceneJson(), "/fluid/density", "continuity");
  dfsph["fluid"]["solver"] = "dfsph";
  EXPECT_EQ(parseError(dfsph),
            "scenes/x.json: fluid.density: expected \"summation\" with fluid.solver \"dfsph\" "
            "(\"continuity\" needs fluid.solver \"wcsph\"), got \"continuity\"");
  json paper = with(completeSceneJson(), "/fluid/density", "continuity");
  paper["fluid"]["solver"] = "wcsph";
  paper["interaction"]["coupling"] = "contact";
  paper["fluid"]["pressure_form"] = "paper";
  EXPECT_EQ(parseError(paper),
            "scenes/x.json: fluid.density: expected \"summation\" with fluid.pressure_form "
            "\"paper\" (\"continuity\" needs \"symmetric\"), got \"continuity\"");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/fluid/density_diffusion", 2)),
            "scenes/x.json: fluid.density_diffusion: expected a number in [0, 1], got 2");
}

TEST(SceneErrors, BadEmittersAndOutletsNameTheKey) {
  EXPECT_EQ(parseError(with(completeSceneJson(), "/emitters/0/shape", "square")),
            "scenes/x.json: emitters[0].shape: expected one of \"disc\", \"rectangle\", got "
            "\"square\"");
  EXPECT_EQ(parseError(without(completeSceneJson(), "/emitters/0/speed")),
            "scenes/x.json: emitters[0].speed: required key is missing (a speed in m/s)");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/emitters/0/speed", 0)),
            "scenes/x.json: emitters[0].speed: expected a number in (0, 10000], got 0");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/emitters/0/edge1", {0, 1, 0})),
            "scenes/x.json: emitters[0].edge1: not a key of a disc emitter; its keys are name, "
            "shape, speed, start, end, center, radius, direction");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/emitters/0/radius", 0.001)),
            "scenes/x.json: emitters[0].radius: expected at least the fluid's spacing 0.02 m, got "
            "0.001");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/emitters/0/direction", {0, 0, 0})),
            "scenes/x.json: emitters[0].direction: expected a direction, got [0, 0, 0]");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/emitters/0/center", {0.2, 1.5, 0})),
            "scenes/x.json: emitters[0].center: expected a point inside the domain box "
            "[-0.1, 0, -0.2] to [1.5, 1.2, 0.3], got [0.2, 1.5, 0]");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/emitters/0/end", 0.1)),
            "scenes/x.json: emitters[0].end: expected a time after emitters[0].start 0.1 s, got "
            "0.1");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/emitters/1/edge2", {0, 0.4, 0})),
            "scenes/x.json: emitters[1].edge2: expected an edge not parallel to emitters[1].edge1 "
            "[0, 0.2, 0], got [0, 0.4, 0]");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/emitters/1/name", "tap")),
            "scenes/x.json: emitters[1].name: expected a name no other emitter has, got \"tap\" "
            "(also emitters[0])");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/outlets/0/max", {1.1, 0.1, 0.25})),
            "scenes/x.json: outlets[0].max: expected a point above outlets[0].min "
            "[1.2, 0, -0.15] on every axis, got [1.1, 0.1, 0.25]");
  EXPECT_EQ(parseError(with(completeSceneJson(), "/outlets/0/max", {1.6, 0.1, 0.25})),
            "scenes/x.json: outlets[0].max: expected a point inside the domain box "
            "[-0.1, 0, -0.2] to [1.5, 1.2, 0.3], got [1.6, 0.1, 0.25]");
  nlohmann::json many = completeSceneJson();
  for (int i = 0; i < 8; ++i) many["outlets"].push_back(many["outlets"][0]);
  EXPECT_EQ(parseError(many), "scenes/x.json: outlets: expected at most 8 outlets, got 9");
}

}  // namespace
}  // namespace sph::scene
