// The fluid's linear momentum, for the tests of Newton's third law between fluid and objects.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "sph/simulation.hpp"

namespace sph::testing {

// x, y, z of Σ m v over the fluid, and Σ m|v| (the scale a tolerance is relative to).
inline std::array<double, 4> fluidMomentum(const Simulation& sim) {
  std::array<double, 4> out{0, 0, 0, 0};
  const ParticleFrame f = sim.frame(false);
  const double m = sim.calibration().mass;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f.kind[i] != std::uint8_t(ParticleKind::Fluid)) continue;  // an attached engine's objects
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      out[a] += m * f.velocity[3 * i + a];
      v2 += double(f.velocity[3 * i + a]) * f.velocity[3 * i + a];
    }
    out[3] += m * std::sqrt(v2);
  }
  return out;
}

}  // namespace sph::testing
