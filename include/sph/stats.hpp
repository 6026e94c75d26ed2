// Per-frame statistics: one row of stats.csv (the command-line contract in README.md).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sph {

// One object of the scene at one instant.
struct ObjectStats {
  std::string name;
  double mass = 0.0;                            // kg
  std::array<double, 3> centreOfMass{0, 0, 0};  // m
  std::array<double, 3> velocity{0, 0, 0};      // of the centre of mass, m/s
  std::array<double, 3> fluidForce{0, 0, 0};    // the fluid's contact force on it, last step, N
  // The other objects' contact push on it over the engine's last finished step, and the walls'
  // on a body that moves, N: what a clamp squeezing a vessel feels (a kinematic object feels it
  // and does not yield).
  std::array<double, 3> contactForce{0, 0, 0};
  // Its centre of mass as built: Simulation::steerObject's offsets are from here.
  std::array<double, 3> startCentre{0, 0, 0};
  std::uint64_t brokenSprings = 0;
  // A vessel filled with incompressible fluid keeps the volume it encloses (boundary coupling):
  // that volume over its shape's. 0 for any other object.
  double volumeRatio = 0.0;
};

// The fluid an emitter has put in, or an outlet taken out, since the start.
struct FlowStats {
  std::string name;
  std::uint64_t particles = 0;
  double mass = 0.0;  // kg
  double rate = 0.0;  // emitters: particles a second while it runs
};

struct FrameStats {
  double time = 0.0;        // s
  std::uint64_t steps = 0;  // steps taken since the start
  double dt = 0.0;          // last time step, s
  std::uint64_t fluidCount = 0;
  std::uint64_t boundaryCount = 0;
  double kineticEnergy = 0.0;        // J
  double meanDensity = 0.0;          // kg/m³
  double averageDensityError = 0.0;  // mean of max (ρ/ρ0 - 1, 0) over the fluid
  double maxDensityError = 0.0;      // max (ρ/ρ0 - 1): compression; a free surface reads low
  double maxSpeed = 0.0;             // m/s
  std::uint64_t surfaceCount = 0;
  std::uint64_t leakedCount = 0;
  std::uint64_t removedCount = 0;  // outside the domain or in an outlet, since the start
  std::uint64_t emittedCount = 0;  // put in by the emitters, since the start
  // Held back since the start: put back into the domain by its "clamp" policy, or their speed
  // limited by the position solver's last guard (half the support radius a substep).
  std::uint64_t clampedCount = 0;
  std::uint64_t contactPairs = 0;  // fluid–object pairs in contact, last step
  // The incompressible solver's iterations summed over every step so far (0 for the weakly
  // compressible one), and its solves that stopped at max_iterations short of the tolerance.
  std::uint64_t densityIterations = 0;
  std::uint64_t divergenceIterations = 0;
  std::uint64_t unconvergedSolves = 0;
  std::vector<ObjectStats> objects;
  double wallMsPerStep = 0.0;  // mean over the steps since the previous row
};

// One row of the scene's probes (scene "probes"): the time k / output.probe_rate, and a value
// for each of Simulation::probeColumns(). A point probe in the air reads NaN.
struct ProbeRow {
  double time = 0.0;
  std::vector<double> values;
};

}  // namespace sph
