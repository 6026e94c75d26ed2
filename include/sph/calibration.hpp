// The values a simulation derives from its scene (Simulation::calibration).
#pragma once

#include <cstdint>

namespace sph {

// The values a run uses, derived from the scene (Meteer 2011, §8.1) unless the scene set them.
struct Calibration {
  double spacing = 0.0;             // d, m
  double supportRadius = 0.0;       // h, m
  double mass = 0.0;                // kg per fluid particle
  double maxExpectedSpeed = 0.0;    // m/s
  double soundSpeed = 0.0;          // c0, m/s
  double stiffness = 0.0;           // k or B of the equation of state
  double kinematicViscosity = 0.0;  // ν used by the viscous time step condition, m²/s
  double initialDt = 0.0;           // s
  double surfaceThreshold = 0.0;    // |∇c| of a surface particle, 1/m
  bool massFromScene = false;
  bool maxExpectedSpeedFromScene = false;
  bool soundSpeedFromScene = false;
  bool stiffnessFromScene = false;
  // Fluid–object contact (Meteer 2011, eqs. 13-15), when the scene has objects.
  double contactStiffness = 0.0;  // k_spring, N/m
  double contactDamping = 0.0;    // k_damping, N·s/m
  double contactShear = 0.0;      // k_shear, N·s/m
  double maxAcceleration = 0.0;   // clamp on a fluid particle's acceleration (§8.3), m/s²
  bool contactStiffnessFromScene = false;
  bool contactDampingFromScene = false;
  bool contactShearFromScene = false;
  bool maxAccelerationFromScene = false;
  // interaction.coupling: the objects are boundary particles of the fluid's pressure solve
  // (Akinci et al. 2012) rather than contact partners.
  bool objectsAsBoundary = false;
  // The position solver (fluid.solver "pbf"): substeps a frame step (time.frame_dt); the
  // constraint gradient's sum on a full lattice, Σ_j |V ∇W_ij|², which scales its relaxation ε
  // and its tensile correction (core/pbf.hpp), 1/m².
  int substeps = 0;
  bool substepsFromScene = false;
  double pbfGradientSquares = 0.0;
  // Its last guard, m/s: a speed that would carry a particle past half the support radius in a
  // substep is limited to this one, and counted (Stats::clampedCount).
  double pbfSpeedGuard = 0.0;
  std::uint64_t fluidParticles = 0;
  std::uint64_t objectParticles = 0;
  std::uint64_t boundaryParticles = 0;
};

}  // namespace sph
