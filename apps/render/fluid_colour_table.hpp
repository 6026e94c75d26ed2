// The fluid's colours as a function of one value per particle, so that a GPU can colour the
// fluid where it lies (CUDA–OpenGL interop) with the same maps as the host: the value's place in
// [lo, hi] picks one of 256 entries made on the host from colour_map.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "sph/core/hostdevice.hpp"
#include "sph/fluid_draw.hpp"

namespace sph::render {

struct FluidColourTable {
  static constexpr int kEntries = 256;
  float lo = 0.0f, hi = 1.0f;
  std::array<std::uint8_t, 4 * kEntries> rgba{};  // alpha 0 when the fluid is hidden
};

// The entry for `value`: its place in [lo, hi], clamped, rounded to the nearest of the 256. A
// range of no width, or a value that is not a number, gives the middle and the bottom.
SPH_HD int fluidColourEntry(float lo, float hi, float value) {
  if (!(hi > lo)) return FluidColourTable::kEntries / 2;
  float t = (value - lo) / (hi - lo);
  t = t > 0.0f ? (t < 1.0f ? t : 1.0f) : 0.0f;  // NaN goes to 0
  return static_cast<int>(t * float(FluidColourTable::kEntries - 1) + 0.5f);
}

// Colours `n` values on the host, RGBA8 each: what the GPU path does, for tests and fallbacks.
void colourFromTable(const FluidColourTable& table, const float* value, std::size_t n,
                     std::uint8_t* rgba);

}  // namespace sph::render
