// The colours of sph's pictures, in one place for `sph render` and the viewer: a perceptual
// sequential map for quantities, a categorical palette for what a particle belongs to. No GL.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "sph/frame.hpp"

namespace sph::render {

struct Rgb {
  float r = 0, g = 0, b = 0;  // each in [0, 1]
};

// What a particle's colour shows.
enum class ColourMode { Kind, Density, Pressure, Speed, Surface };

// "kind", "density", "pressure", "speed", "surface".
const char* colourModeName(ColourMode mode);
std::optional<ColourMode> parseColourMode(const std::string& name);
// Density, pressure and speed go through the sequential map over a range; the others do not.
bool usesRange(ColourMode mode);

struct ValueRange {
  float min = 0, max = 1;
};

// The sequential map at t in [0, 1] (clamped): dark blue-violet through teal and green to
// yellow, with lightness rising monotonically so that order reads without a legend.
Rgb sequentialColour(float t);

// `value` placed in `range` (clamped to its ends) and looked up in the sequential map. A range of
// zero width gives the map's middle.
Rgb mapValue(float value, ValueRange range);

// Fluid: water blue; walls: grey; objects: one colour per object index, repeating after a dozen.
Rgb kindColour(ParticleKind kind, std::int32_t object);

// Surface mode: particles on the free (or object) surface against the rest.
Rgb surfaceColour(bool onSurface);

// 8-bit channel for a colour in [0, 1], rounded.
std::uint8_t toByte(float channel);

}  // namespace sph::render
