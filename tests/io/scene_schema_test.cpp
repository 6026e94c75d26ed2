// Tests of src/io/scene_schema: the nearest-key suggestion and key paths.
#include "io/scene_schema.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sph::io
