// The description of a simulation as read from a scene file: geometry, material, parameters,
// output. Plain data; `io/scene_loader` fills it from JSON, `sim/calibration` derives the rest.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "sph/core/options.hpp"

namespace sph {

using Vec3d = std::array<double, 3>;

enum class OutsidePolicy { Remove, Clamp };
enum class FrameFormat { Vtp, Ply, Csv, None };

struct AxisBox {
  Vec3d min{0, 0, 0};
  Vec3d max{0, 0, 0};
};

// A block of fluid sampled on a cubic lattice of the fluid spacing. A hydrostatic block starts
// compressed as it would rest under gravity, so a tank starts at rest instead of dropping into
// its own compression and ringing.
struct FluidBlock {
  AxisBox box;
  Vec3d velocity{0, 0, 0};
  bool hydrostatic = false;
};

// A tank whose inner faces are `box`, built from `layers` layers of boundary particles
// (Akinci et al. 2012). Without a lid unless `closed`.
struct WallTank {
  AxisBox box;
  int layers = 2;
  bool closed = false;
};

struct DomainDesc {
  AxisBox box;
  OutsidePolicy outside = OutsidePolicy::Remove;
  bool dampedBox = false;  // seed 2: reflect at the domain faces, velocity scaled by -damping
  double damping = 0.5;
};

struct FluidDesc {
  double restDensity = 1000.0;  // kg/m³
  double spacing = 0.01;        // lattice spacing d, m
  double supportRatio = 2.0;    // h / d
  KernelKind kernel = KernelKind::Muller;
  EquationOfState eos = EquationOfState::Linear;
  bool clampNegativePressure = true;
  PressureForm pressureForm = PressureForm::Symmetric;
  ViscosityModel viscosityModel = ViscosityModel::Artificial;
  double viscosity = 0.0;           // μ (Pa·s) for Müller; α (dimensionless) for artificial
  double wallFriction = 0.0;        // fraction of the fluid viscosity applied against walls
  double surfaceTension = 0.0;      // σ (N/m); 0 disables
  // |∇c| (1/m) above which a particle is on the surface and surface tension acts; unset: 0.22/h,
  // seed 2's 7.065 at its h = 1/32, scaled to ours.
  std::optional<double> surfaceThreshold;
  std::vector<FluidBlock> blocks;
};

// Values `sim/calibration` derives unless the scene sets them.
struct CalibrationDesc {
  std::optional<double> mass;              // kg per particle
  std::optional<double> maxExpectedSpeed;  // m/s; default sqrt(2 g H)
  std::optional<double> speedOfSound;      // m/s; default 10 × max expected speed
  std::optional<double> stiffness;         // k or B, by equation of state
};

struct TimeDesc {
  double duration = 1.0;         // simulated seconds
  double cfl = 0.4;              // dt ≤ cfl h / (c0 + vmax)
  double forceFactor = 0.25;     // dt ≤ forceFactor sqrt(h / amax)
  double viscousFactor = 0.125;  // dt ≤ viscousFactor h² / ν
  double maxDt = 1e-2;
  std::optional<double> fixedDt;
};

struct OutputDesc {
  double fps = 30.0;
  FrameFormat format = FrameFormat::Vtp;
};

struct FailureDesc {
  double maxDensityError = 0.5;  // compression ρ/ρ0 - 1 past which the run stops as failed
};

struct Scene {
  std::string name;
  std::string description;
  std::string sourcePath;  // file it was read from, for messages
  DomainDesc domain;
  Vec3d gravity{0, -9.81, 0};
  FluidDesc fluid;
  std::vector<WallTank> walls;
  CalibrationDesc calibration;
  TimeDesc time;
  OutputDesc output;
  FailureDesc failure;
};

}  // namespace sph
