#include "colour_map.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace sph::render {

namespace {

// Control points of the sequential map, evenly spaced in t, approximating viridis (van der Walt
// and Smith, 2015, public domain): dark blue-violet → blue → teal → green → yellow. Lightness
// rises monotonically, so the map reads in greyscale and for the common colour deficiencies.
constexpr Rgb kSequential[] = {
    {0.267f, 0.005f, 0.329f}, {0.283f, 0.141f, 0.458f}, {0.254f, 0.265f, 0.530f},
    {0.207f, 0.372f, 0.553f}, {0.164f, 0.471f, 0.558f}, {0.128f, 0.567f, 0.551f},
    {0.135f, 0.659f, 0.518f}, {0.267f, 0.749f, 0.441f}, {0.478f, 0.821f, 0.318f},
    {0.741f, 0.873f, 0.150f}, {0.993f, 0.906f, 0.144f},
};

// Object colours: distinct hues at similar lightness, none close to the fluid's blue or the
// walls' grey (objects are drawn among both).
constexpr Rgb kObjectPalette[] = {
    {0.85f, 0.37f, 0.33f}, {0.95f, 0.65f, 0.20f}, {0.55f, 0.75f, 0.30f}, {0.75f, 0.45f, 0.75f},
    {0.90f, 0.80f, 0.35f}, {0.35f, 0.70f, 0.60f}, {0.85f, 0.55f, 0.60f}, {0.65f, 0.50f, 0.35f},
    {0.60f, 0.85f, 0.85f}, {0.95f, 0.50f, 0.10f}, {0.55f, 0.55f, 0.90f}, {0.80f, 0.80f, 0.80f},
};

constexpr Rgb kFluid{0.20f, 0.50f, 0.90f};
constexpr Rgb kWall{0.55f, 0.55f, 0.58f};
constexpr Rgb kSurface{0.95f, 0.95f, 0.98f};
constexpr Rgb kInterior{0.16f, 0.30f, 0.55f};

Rgb lerp(const Rgb& a, const Rgb& b, float s) {
  return {a.r + (b.r - a.r) * s, a.g + (b.g - a.g) * s, a.b + (b.b - a.b) * s};
}

struct ModeName {
  ColourMode mode;
  const char* name;
};
constexpr ModeName kModeNames[] = {{ColourMode::Kind, "kind"},
                                   {ColourMode::Density, "density"},
                                   {ColourMode::Pressure, "pressure"},
                                   {ColourMode::Speed, "speed"},
                                   {ColourMode::Surface, "surface"}};

}  // namespace

const char* colourModeName(ColourMode mode) {
  for (const ModeName& m : kModeNames)
    if (m.mode == mode) return m.name;
  return "kind";
}

std::optional<ColourMode> parseColourMode(const std::string& name) {
  for (const ModeName& m : kModeNames)
    if (name == m.name) return m.mode;
  return std::nullopt;
}

bool usesRange(ColourMode mode) {
  return mode == ColourMode::Density || mode == ColourMode::Pressure || mode == ColourMode::Speed;
}

Rgb sequentialColour(float t) {
  constexpr int kSegments = static_cast<int>(std::size(kSequential)) - 1;
  if (!(t > 0.0f)) return kSequential[0];  // also NaN: the low end rather than garbage
  if (t >= 1.0f) return kSequential[kSegments];
  const float x = t * static_cast<float>(kSegments);
  const int segment = std::min(static_cast<int>(x), kSegments - 1);
  return lerp(kSequential[segment], kSequential[segment + 1], x - static_cast<float>(segment));
}

Rgb mapValue(float value, ValueRange range) {
  const float width = range.max - range.min;
  if (!(std::abs(width) > 0.0f)) return sequentialColour(0.5f);
  return sequentialColour((value - range.min) / width);
}

Rgb kindColour(ParticleKind kind, std::int32_t object) {
  switch (kind) {
    case ParticleKind::Fluid:
      return kFluid;
    case ParticleKind::Boundary:
      return kWall;
    case ParticleKind::Object:
      break;
  }
  const std::int32_t count = static_cast<std::int32_t>(std::size(kObjectPalette));
  return kObjectPalette[object < 0 ? 0 : object % count];
}

Rgb surfaceColour(bool onSurface) {
  return onSurface ? kSurface : kInterior;
}

std::uint8_t toByte(float channel) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f));
}

}  // namespace sph::render
