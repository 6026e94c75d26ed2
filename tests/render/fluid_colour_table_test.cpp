// The table a GPU colours the fluid with gives the colours particleColour gives, for every mode.
#include "fluid_colour_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "particle_colours.hpp"

namespace sph::render {
namespace {

// Fluid particles with densities, pressures and speeds spread over and past a range, and every
// other one on the surface.
ParticleFrame spreadFluid(std::size_t n) {
  ParticleFrame f;
  for (std::size_t i = 0; i < n; ++i) {
    const float s = float(i) / float(n - 1);  // 0 .. 1
    f.id.push_back(std::uint32_t(i));
    f.position.insert(f.position.end(), {0.0f, 0.0f, 0.0f});
    f.velocity.insert(f.velocity.end(), {3.0f * s, -1.5f * s, 0.0f});
    f.density.push_back(985.0f + 30.0f * s);
    f.pressure.push_back(-100.0f + 1400.0f * s);
    f.kind.push_back(std::uint8_t(ParticleKind::Fluid));
    f.object.push_back(-1);
    f.surface.push_back(std::uint8_t(i % 2));
  }
  return f;
}

float valueFor(const ParticleFrame& f, std::size_t i, ColourMode mode) {
  return mode == ColourMode::Surface ? float(f.surface[i]) : particleValue(f, i, mode);
}

TEST(FluidColourTable, ColoursTheFluidAsTheHostDoesWithinOneStep) {
  const ParticleFrame frame = spreadFluid(501);
  const ValueRange ranges[] = {{990.0f, 1010.0f}, {0.0f, 1000.0f}, {0.0f, 2.5f}};
  for (ColourMode mode : {ColourMode::Kind, ColourMode::Density, ColourMode::Pressure,
                          ColourMode::Speed, ColourMode::Surface}) {
    const ValueRange range = mode == ColourMode::Density    ? ranges[0]
                             : mode == ColourMode::Pressure ? ranges[1]
                                                            : ranges[2];
    const FluidColourTable table = fluidColourTable(mode, range, true);
    std::vector<float> values(frame.size());
    for (std::size_t i = 0; i < frame.size(); ++i) values[i] = valueFor(frame, i, mode);
    std::vector<std::uint8_t> onGpu(4 * frame.size());
    colourFromTable(table, values.data(), values.size(), onGpu.data());
    const std::vector<std::uint8_t> host = particleColours(frame, mode, range, ParticleFilter{});
    int worst = 0;
    for (std::size_t k = 0; k < host.size(); ++k)
      worst = std::max(worst, std::abs(int(host[k]) - int(onGpu[k])));
    // Half a step of 1/255 along the map moves a channel by at most 2 of 255.
    EXPECT_LE(worst, 2) << colourModeName(mode);
  }
}

TEST(FluidColourTable, HiddenFluidHasZeroAlphaAndKindIsOneColour) {
  const FluidColourTable hidden = fluidColourTable(ColourMode::Density, {0, 1}, false);
  for (int k = 0; k < FluidColourTable::kEntries; ++k) EXPECT_EQ(hidden.rgba[4 * k + 3], 0);
  const FluidColourTable kind = fluidColourTable(ColourMode::Kind, {0, 1}, true);
  const Rgb blue = kindColour(ParticleKind::Fluid, -1);
  for (int k = 0; k < FluidColourTable::kEntries; ++k) {
    EXPECT_EQ(kind.rgba[4 * k + 0], toByte(blue.r));
    EXPECT_EQ(kind.rgba[4 * k + 2], toByte(blue.b));
  }
}

TEST(FluidColourTable, EntriesClampAndSurviveBadRanges) {
  EXPECT_EQ(fluidColourEntry(0.0f, 1.0f, -5.0f), 0);
  EXPECT_EQ(fluidColourEntry(0.0f, 1.0f, 5.0f), 255);
  EXPECT_EQ(fluidColourEntry(0.0f, 1.0f, 0.5f), 128);
  EXPECT_EQ(fluidColourEntry(0.0f, 1.0f, std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(fluidColourEntry(3.0f, 3.0f, 3.0f), 128);
  EXPECT_EQ(quantityShown(ColourMode::Kind), FluidQuantity::None);
  EXPECT_EQ(quantityShown(ColourMode::Surface), FluidQuantity::Surface);
}

}  // namespace
}  // namespace sph::render
