// The numbers every pass reads, derived once by sim/calibration. Passed by value to the
// per-particle code (constant memory on the GPU, Meteer 2011, §5.3).
#pragma once

#include <cstdint>

#include "sph/core/grid.hpp"
#include "sph/core/options.hpp"
#include "sph/core/periodic.hpp"
#include "sph/core/vec.hpp"

namespace sph::fluid {

struct FluidParameters {
  KernelKind kernel;
  EquationOfState eos;
  PressureForm pressureForm;
  ViscosityModel viscosityModel;
  bool clampNegativePressure;
  bool pressureForces;     // false: the incompressible solver gives the pressure (DFSPH)
  float h;                 // support radius, m
  float mass;              // per fluid particle, kg
  float restDensity;       // kg/m³
  float stiffness;         // k or B of the equation of state
  float soundSpeed;        // c0, m/s
  float viscosity;         // μ (Müller) or α (artificial)
  float wallFriction;      // scale of the viscous term against boundary particles
  float surfaceTension;    // σ, N/m
  float surfaceThreshold;  // |∇c| above which a particle is on the surface, 1/m
  Vec3 gravity;            // m/s²
  // Density integrated by the continuity equation (weakly compressible solver), with δ-SPH's
  // diffusion of coefficient densityDiffusion (δ); else summed from the neighbours each step.
  bool continuityDensity;
  float densityDiffusion;
  Periodicity periodic;  // the domain's periodic axes; none by default
};

// How the CPU's passes take neighbours: a SIMD batch at a time, or one at a time as the GPU
// does, the reference the first is tested and timed against. The GPU ignores it.
enum class NeighborWalk { Batched, OneAtATime };

constexpr std::uint32_t kOutletSlots = 8;

// Boxes whose fluid is removed (the scene's outlets), and counted by box.
struct Outlets {
  std::uint32_t count = 0;
  Vec3 min[kOutletSlots];
  Vec3 max[kOutletSlots];
};

// The explicit domain: what lies outside is removed or clamped; the damped box of the
// 2021 CUDA SPH tutorial reflects at its faces. What enters an outlet is removed.
struct DomainParameters {
  Vec3 min, max;
  bool clampOutside;
  bool dampedBox;
  float damping;
  Outlets outlets;
  Periodicity periodic;  // the same as FluidParameters::periodic
};

}  // namespace sph::fluid
