// The colour map's ends and middle, known densities' colours, the categorical palette and the
// ranges taken from the fluid.
#include "colour_map.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "particle_colours.hpp"

namespace sph::render {
namespace {

using Bytes = std::array<int, 3>;

Bytes bytes(const Rgb& c) {
  return {toByte(c.r), toByte(c.g), toByte(c.b)};
}

ParticleFrame fluidWithDensities(const std::vector<float>& densities) {
  ParticleFrame f;
  for (std::size_t i = 0; i < densities.size(); ++i) {
    f.id.push_back(static_cast<std::uint32_t>(i));
    f.position.insert(f.position.end(), {0.0f, 0.0f, 0.0f});
    f.velocity.insert(f.velocity.end(), {3.0f, 4.0f, 0.0f});  // speed 5
    f.density.push_back(densities[i]);
    f.pressure.push_back(10.0f * static_cast<float>(i));
    f.kind.push_back(0);
    f.object.push_back(-1);
    f.surface.push_back(0);
  }
  return f;
}

TEST(ColourMap, EndsAreDarkVioletAndYellow) {
  EXPECT_EQ(bytes(sequentialColour(0.0f)), (Bytes{68, 1, 84}));
  EXPECT_EQ(bytes(sequentialColour(1.0f)), (Bytes{253, 231, 37}));
  // Outside [0, 1] (and NaN) the map holds its ends.
  EXPECT_EQ(bytes(sequentialColour(-3.0f)), (Bytes{68, 1, 84}));
  EXPECT_EQ(bytes(sequentialColour(7.0f)), (Bytes{253, 231, 37}));
  EXPECT_EQ(bytes(sequentialColour(std::numeric_limits<float>::quiet_NaN())), (Bytes{68, 1, 84}));
}

TEST(ColourMap, LightnessRisesAlongTheMap) {
  auto luma = [](const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; };
  for (int k = 1; k <= 100; ++k)
    EXPECT_GT(luma(sequentialColour(k / 100.0f)), luma(sequentialColour((k - 1) / 100.0f))) << k;
}

TEST(ColourMap, KnownDensitiesGetTheirColours) {
  const ValueRange range{990.0f, 1010.0f};
  EXPECT_EQ(bytes(mapValue(990.0f, range)), (Bytes{68, 1, 84}));      // the low end
  EXPECT_EQ(bytes(mapValue(1000.0f, range)), (Bytes{33, 145, 141}));  // the middle: teal
  EXPECT_EQ(bytes(mapValue(1010.0f, range)), (Bytes{253, 231, 37}));  // the high end
  EXPECT_EQ(bytes(mapValue(1500.0f, range)), (Bytes{253, 231, 37}));  // clamped
  // Between control points the map interpolates linearly: 995 is t = 0.25, halfway between the
  // third (t = 0.2) and fourth (t = 0.3) points.
  const Rgb quarter = mapValue(995.0f, range);
  EXPECT_NEAR(quarter.r, 0.5f * (0.254f + 0.207f), 1e-5f);
  EXPECT_NEAR(quarter.g, 0.5f * (0.265f + 0.372f), 1e-5f);
  EXPECT_NEAR(quarter.b, 0.5f * (0.530f + 0.553f), 1e-5f);
  // A range of zero width gives the middle instead of dividing by zero.
  EXPECT_EQ(bytes(mapValue(5.0f, {1.0f, 1.0f})), (Bytes{33, 145, 141}));
}

TEST(ColourMap, ParticleColoursFollowTheMode) {
  const ParticleFrame frame = fluidWithDensities({990.0f, 1000.0f, 1010.0f});
  const std::vector<std::uint8_t> rgba =
      particleColours(frame, ColourMode::Density, {990.0f, 1010.0f}, ParticleFilter{});
  ASSERT_EQ(rgba.size(), 12u);
  EXPECT_EQ((Bytes{rgba[0], rgba[1], rgba[2]}), (Bytes{68, 1, 84}));
  EXPECT_EQ((Bytes{rgba[4], rgba[5], rgba[6]}), (Bytes{33, 145, 141}));
  EXPECT_EQ((Bytes{rgba[8], rgba[9], rgba[10]}), (Bytes{253, 231, 37}));
  EXPECT_EQ(rgba[3], 255);
  EXPECT_FLOAT_EQ(particleValue(frame, 0, ColourMode::Speed), 5.0f);
  EXPECT_FLOAT_EQ(particleValue(frame, 2, ColourMode::Pressure), 20.0f);
}

TEST(ColourMap, KindsHaveTheirOwnColours) {
  const Bytes fluid = bytes(kindColour(ParticleKind::Fluid, -1));
  const Bytes wall = bytes(kindColour(ParticleKind::Boundary, -1));
  EXPECT_GT(fluid[2], fluid[0] + 80);  // water blue
  EXPECT_EQ(wall[0], wall[1]);         // grey
  EXPECT_NEAR(wall[2], wall[0], 10);
  for (int a = 0; a < 12; ++a)
    for (int b = a + 1; b < 12; ++b)
      EXPECT_NE(bytes(kindColour(ParticleKind::Object, a)),
                bytes(kindColour(ParticleKind::Object, b)))
          << "objects " << a << " and " << b;
  EXPECT_NE(bytes(kindColour(ParticleKind::Object, 0)), fluid);
  EXPECT_NE(bytes(kindColour(ParticleKind::Object, 0)), wall);
}

TEST(ColourMap, HiddenParticlesHaveZeroAlpha) {
  ParticleFrame frame = fluidWithDensities({1000.0f, 1000.0f, 1000.0f});
  frame.kind = {0, 1, 2};
  frame.object = {-1, -1, 4};
  ParticleFilter filter;
  filter.boundary = false;
  const std::vector<std::uint8_t> rgba =
      particleColours(frame, ColourMode::Kind, {0.0f, 1.0f}, filter);
  EXPECT_EQ(rgba[3], 255);
  EXPECT_EQ(rgba[7], 0);
  EXPECT_EQ(rgba[11], 255);
  EXPECT_EQ((Bytes{rgba[8], rgba[9], rgba[10]}), bytes(kindColour(ParticleKind::Object, 4)));
}

TEST(ColourMap, ACutPlaneHidesObjectsAndWallsInFrontButNeverTheFluid) {
  ParticleFrame frame = fluidWithDensities({1000.0f, 1000.0f, 1000.0f, 1000.0f});
  frame.kind = {2, 2, 1, 0};
  frame.object = {0, 0, -1, -1};
  frame.position = {0, 0, 1, 0, 0, -1, 0, 0, 2, 0, 0, 3};  // z = 1, -1, 2, 3
  ParticleFilter filter;
  filter.cut = CutPlane{{0, 0, 0}, {0, 0, -1}};  // keeps z < 0: the camera looks along -z
  EXPECT_FALSE(particleShown(frame, 0, filter));  // object in front
  EXPECT_TRUE(particleShown(frame, 1, filter));   // object behind
  EXPECT_FALSE(particleShown(frame, 2, filter));  // wall in front
  EXPECT_TRUE(particleShown(frame, 3, filter));   // fluid, in front, still shown
}

TEST(ColourMap, DensityRangeIsCentredOnTheMedian) {
  std::vector<float> densities;
  for (int i = 0; i <= 100; ++i) densities.push_back(1000.0f + 0.1f * static_cast<float>(i - 50));
  densities[0] = 700.0f;  // a splash: outside the 2nd-98th percentile
  const ParticleFrame frame = fluidWithDensities(densities);
  const ValueRange range = rangeFromFrames({&frame}, ColourMode::Density);
  EXPECT_NEAR(0.5f * (range.min + range.max), 1000.0f, 1e-3f);
  EXPECT_NEAR(range.max, 1004.8f, 1e-3f);
  const ValueRange speed = rangeFromFrames({&frame}, ColourMode::Speed);
  EXPECT_FLOAT_EQ(speed.min, 0.0f);
  EXPECT_GT(speed.max, speed.min);  // every speed is 5: never of zero width
}

TEST(ColourMap, ModeNamesRoundTrip) {
  for (ColourMode mode : {ColourMode::Kind, ColourMode::Density, ColourMode::Pressure,
                          ColourMode::Speed, ColourMode::Surface})
    EXPECT_EQ(parseColourMode(colourModeName(mode)), mode);
  EXPECT_FALSE(parseColourMode("temperature").has_value());
}

}  // namespace
}  // namespace sph::render
