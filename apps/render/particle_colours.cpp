#include "particle_colours.hpp"

#include <algorithm>
#include <cmath>

namespace sph::render {

namespace {

float percentile(std::vector<float>& values, double fraction) {
  const std::size_t k = static_cast<std::size_t>(fraction * double(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

}  // namespace

float particleValue(const ParticleFrame& frame, std::size_t i, ColourMode mode) {
  switch (mode) {
    case ColourMode::Density:
      return frame.density[i];
    case ColourMode::Pressure:
      return frame.pressure[i];
    case ColourMode::Speed: {
      const float* v = &frame.velocity[3 * i];
      return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    case ColourMode::Kind:
    case ColourMode::Surface:
      break;
  }
  return 0.0f;
}

ValueRange rangeFromFrames(const std::vector<const ParticleFrame*>& frames, ColourMode mode) {
  std::vector<float> values;
  for (const ParticleFrame* frame : frames)
    for (std::size_t i = 0; i < frame->size(); ++i)
      if (frame->kind[i] == static_cast<std::uint8_t>(ParticleKind::Fluid)) {
        const float value = particleValue(*frame, i, mode);
        if (std::isfinite(value)) values.push_back(value);
      }
  if (values.empty() || !usesRange(mode)) return {0.0f, 1.0f};
  ValueRange range{percentile(values, 0.02), percentile(values, 0.98)};
  if (mode == ColourMode::Density) {
    const float median = percentile(values, 0.5);
    const float half = std::max({range.max - median, median - range.min, 1e-3f * median});
    range = {median - half, median + half};
  } else if (range.min > 0.0f) {
    range.min = 0.0f;
  }
  if (!(range.max > range.min)) range.max = range.min + std::max(1e-6f, std::abs(range.min));
  return range;
}

Rgb particleColour(const ParticleFrame& frame, std::size_t i, ColourMode mode, ValueRange range) {
  const auto kind = static_cast<ParticleKind>(frame.kind[i]);
  switch (mode) {
    case ColourMode::Kind:
      return kindColour(kind, frame.object[i]);
    case ColourMode::Surface:
      if (kind == ParticleKind::Boundary) return kindColour(kind, -1);
      return surfaceColour(i < frame.surface.size() && frame.surface[i] != 0);
    case ColourMode::Density:
    case ColourMode::Pressure:
    case ColourMode::Speed:
      break;
  }
  // Walls and objects keep their category colours: their density and pressure are not the
  // fluid's, and the map over them would only hide the fluid.
  if (kind != ParticleKind::Fluid) return kindColour(kind, frame.object[i]);
  return mapValue(particleValue(frame, i, mode), range);
}

bool particleShown(const ParticleFrame& frame, std::size_t i, const ParticleFilter& filter) {
  const auto kind = static_cast<ParticleKind>(frame.kind[i]);
  if (filter.cut && kind != ParticleKind::Fluid) {
    const Vec3f p{frame.position[3 * i], frame.position[3 * i + 1], frame.position[3 * i + 2]};
    if (dot(subtract(p, filter.cut->point), filter.cut->normal) < 0.0f) return false;
  }
  switch (kind) {
    case ParticleKind::Fluid:
      return filter.fluid;
    case ParticleKind::Boundary:
      return filter.boundary;
    case ParticleKind::Object:
      return filter.objects;
  }
  return false;
}

std::vector<std::uint8_t> particleColours(const ParticleFrame& frame, ColourMode mode,
                                          ValueRange range, const ParticleFilter& filter) {
  std::vector<std::uint8_t> rgba(4 * frame.size());
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const Rgb c = particleColour(frame, i, mode, range);
    rgba[4 * i + 0] = toByte(c.r);
    rgba[4 * i + 1] = toByte(c.g);
    rgba[4 * i + 2] = toByte(c.b);
    rgba[4 * i + 3] = particleShown(frame, i, filter) ? 255 : 0;
  }
  return rgba;
}

FluidQuantity quantityShown(ColourMode mode) {
  switch (mode) {
    case ColourMode::Density:
      return FluidQuantity::Density;
    case ColourMode::Pressure:
      return FluidQuantity::Pressure;
    case ColourMode::Speed:
      return FluidQuantity::Speed;
    case ColourMode::Surface:
      return FluidQuantity::Surface;
    case ColourMode::Kind:
      break;
  }
  return FluidQuantity::None;
}

FluidColourTable fluidColourTable(ColourMode mode, ValueRange range, bool fluidShown) {
  FluidColourTable table;
  if (usesRange(mode)) {
    table.lo = range.min;
    table.hi = range.max;
  }
  constexpr int last = FluidColourTable::kEntries - 1;
  for (int k = 0; k <= last; ++k) {
    const float t = float(k) / float(last);
    Rgb c;
    switch (mode) {
      case ColourMode::Kind:
        c = kindColour(ParticleKind::Fluid, -1);
        break;
      case ColourMode::Surface:
        c = surfaceColour(k > last / 2);  // the values are 0 and 1
        break;
      case ColourMode::Density:
      case ColourMode::Pressure:
      case ColourMode::Speed:
        c = sequentialColour(t);
        break;
    }
    table.rgba[4 * k + 0] = toByte(c.r);
    table.rgba[4 * k + 1] = toByte(c.g);
    table.rgba[4 * k + 2] = toByte(c.b);
    table.rgba[4 * k + 3] = fluidShown ? 255 : 0;
  }
  return table;
}

void colourFromTable(const FluidColourTable& table, const float* value, std::size_t n,
                     std::uint8_t* rgba) {
  for (std::size_t i = 0; i < n; ++i) {
    const int k = fluidColourEntry(table.lo, table.hi, value[i]);
    std::copy_n(&table.rgba[4 * k], 4, &rgba[4 * i]);
  }
}

}  // namespace sph::render
