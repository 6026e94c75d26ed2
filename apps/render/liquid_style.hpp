// How a liquid looks in the liquid view (liquid_surface.hpp): its colour where it is deep, and
// how fast it absorbs the light through it, by colour channel (Beer–Lambert: a layer t thick
// lets exp(−a t) through). Blood is dark red and opaque within a few millimetres; water clear,
// turning blue over tens of centimetres.
#pragma once

#include <string>

#include "colour_map.hpp"

namespace sph::render {

struct LiquidStyle {
  Rgb colour{0.18f, 0.50f, 0.80f};     // what a deep layer scatters back, lit
  Rgb absorption{40.0f, 12.0f, 6.0f};  // 1/m per channel
  // Passes of the depth's smoothing filter (each a horizontal and a vertical sweep), and its
  // reach in particle radii: enough to smooth the spheres into one surface, not so much that
  // it rounds off the liquid's edges.
  int smoothingPasses = 3;
  float smoothingReach = 5.0f;
};

// Whether to draw the fluid as shaded spheres, or as a liquid surface.
enum class Look { Particles, Liquid };

// The look asked for ("liquid", "particles"), else the scene's, except that a quantity (a
// colour mode other than kind) is read off the particles.
inline Look chooseLook(const std::string& asked, bool sceneWantsParticles, ColourMode colour) {
  if (!asked.empty()) return asked == "particles" ? Look::Particles : Look::Liquid;
  if (colour != ColourMode::Kind || sceneWantsParticles) return Look::Particles;
  return Look::Liquid;
}

}  // namespace sph::render
