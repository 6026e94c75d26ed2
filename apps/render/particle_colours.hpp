// A frame's particles through the colour map: the quantity each shows, the range it is mapped
// over, and which particles are drawn at all. No GL, so `sph render` and the tests share it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "camera.hpp"
#include "colour_map.hpp"
#include "fluid_colour_table.hpp"
#include "sph/frame.hpp"

namespace sph::render {

// Walls and objects on the near side of a plane are left out, to show the fluid they hide
// (the blood inside a vessel).
struct CutPlane {
  Vec3f point{0, 0, 0};
  Vec3f normal{0, 0, 1};  // toward the side kept
};

struct ParticleFilter {
  bool fluid = true;
  bool boundary = true;  // walls
  bool objects = true;
  std::optional<CutPlane> cut;  // never cuts the fluid
};

// The quantity shown for particle i: density (kg/m³), pressure (Pa) or speed (m/s); 0 for modes
// that map no quantity.
float particleValue(const ParticleFrame& frame, std::size_t i, ColourMode mode);

// A range for `mode` taken from the fluid of `frames` (objects and walls have no SPH density or
// pressure of their own): the 2nd to 98th percentile, so that a few splashing or compressed
// particles do not wash out the rest; density is centred on the median (about the rest density),
// pressure and speed start at 0 when nothing is below it. Never of zero width.
ValueRange rangeFromFrames(const std::vector<const ParticleFrame*>& frames, ColourMode mode);

// The colour of particle i.
Rgb particleColour(const ParticleFrame& frame, std::size_t i, ColourMode mode, ValueRange range);

bool particleShown(const ParticleFrame& frame, std::size_t i, const ParticleFilter& filter);

// RGBA8 per particle, alpha 0 for particles the filter hides.
std::vector<std::uint8_t> particleColours(const ParticleFrame& frame, ColourMode mode,
                                          ValueRange range, const ParticleFilter& filter);

// What a fluid drawn from the GPU carries beside its position for `mode` (None for kind).
FluidQuantity quantityShown(ColourMode mode);

// The table that colours the fluid like particleColour does, from the value quantityShown asks
// for, within 1/255 of the map; alpha 0 when the fluid is hidden.
FluidColourTable fluidColourTable(ColourMode mode, ValueRange range, bool fluidShown);

}  // namespace sph::render
