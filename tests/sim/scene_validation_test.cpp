// A scene built in code is held to the rules a scene file is: Simulation checks it with the
// loader's own validateScene before anything is made.
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "scene_builders.hpp"
#include "sph/error.hpp"
#include "sph/scene_file.hpp"
#include "sph/simulation.hpp"

namespace sph {
namespace {

// What Simulation's constructor says of `scene`, or "accepted".
std::string refusal(const Scene& scene) {
  try {
    Simulation sim(scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(SceneValidation, ASimulationRefusesWhatTheLoaderRefuses) {
  const Scene tank = testing::restingTank(0.02, 0.1, 0.1);
  ASSERT_EQ(refusal(tank), "accepted");

  // A key's own limits.
  Scene spacing = tank;
  spacing.fluid.spacing = -0.02;
  EXPECT_EQ(refusal(spacing),
            "resting_tank (test): fluid.spacing: expected a number in [1e-06, 100], got -0.02");
  Scene cfl = tank;
  cfl.time.cfl = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(refusal(cfl).find("resting_tank (test): time.cfl: expected"), std::string::npos)
      << refusal(cfl);

  // Checks across keys.
  Scene probe = tank;
  ProbeDesc outside;
  outside.name = "far";
  outside.position = {5, 0, 0};
  probe.probes.push_back(outside);
  EXPECT_NE(refusal(probe).find("resting_tank (test): probes[0].position: expected a point "
                                "inside the domain box"),
            std::string::npos)
      << refusal(probe);
  Scene coupling = tank;
  coupling.interaction.coupling = ObjectCoupling::Boundary;
  EXPECT_NE(refusal(coupling).find("interaction.coupling: expected \"contact\" with fluid.solver"),
            std::string::npos)
      << refusal(coupling);
  Scene block = tank;
  block.fluid.blocks[0].box.max = {-0.05, 0.1, 0.1};  // max below min
  EXPECT_NE(refusal(block).find("fluid.blocks[0]"), std::string::npos) << refusal(block);

  // The same words as the loader's, for the same scene.
  try {
    parseScene(sceneToJsonText(spacing), "resting_tank (test)");
    FAIL() << "the loader accepted a negative spacing";
  } catch (const InputError& e) {
    EXPECT_EQ(refusal(spacing), e.what());
  }
}

TEST(SceneValidation, UnnamedElementsAreNamedAsTheLoaderNamesThem) {
  Scene scene = testing::restingTank(0.02, 0.1, 0.1);
  ASSERT_TRUE(scene.walls[0].name.empty());
  ProbeDesc force;
  force.kind = ProbeKind::Force;
  force.wall = "wall0";
  scene.probes.push_back(force);
  const Scene named = validateScene(scene);
  EXPECT_EQ(named.walls[0].name, "wall0");
  EXPECT_EQ(named.probes[0].name, "probe0");
  EXPECT_EQ(refusal(scene), "accepted");
  // What a file would say of the same scene: it reads back to the same names.
  EXPECT_EQ(parseScene(sceneToJsonText(named), "resting_tank (test)").walls[0].name, "wall0");

  scene.probes[0].wall = "tank";
  EXPECT_NE(refusal(scene).find("probes[0].wall: expected the name of a wall (wall0), got "
                                "\"tank\""),
            std::string::npos)
      << refusal(scene);
}

}  // namespace
}  // namespace sph
