// Per-frame statistics: one row of stats.csv (DESIGN.md's command-line contract).
#pragma once

#include <cstdint>

namespace sph {

struct FrameStats {
  double time = 0.0;        // s
  std::uint64_t steps = 0;  // steps taken since the start
  double dt = 0.0;          // last time step, s
  std::uint64_t fluidCount = 0;
  std::uint64_t boundaryCount = 0;
  double kineticEnergy = 0.0;    // J
  double meanDensity = 0.0;      // kg/m³
  double maxDensityError = 0.0;  // max (ρ/ρ0 - 1): compression; a free surface reads low
  double maxSpeed = 0.0;         // m/s
  std::uint64_t surfaceCount = 0;
  std::uint64_t leakedCount = 0;
  std::uint64_t removedCount = 0;
  double wallMsPerStep = 0.0;  // mean over the steps since the previous row
};

}  // namespace sph
