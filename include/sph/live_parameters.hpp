// The parameters a running simulation takes new values of (Simulation::setLiveParameters).
#pragma once

#include "sph/scene.hpp"  // Vec3d

namespace sph {

// What may change while a simulation runs (the viewer's panel), in the scene's units.
struct LiveParameters {
  double viscosity = 0.0;       // fluid.viscosity: μ (Müller) or α (artificial)
  double stiffness = 0.0;       // of the equation of state; the speed of sound follows it
  Vec3d gravity{0, 0, 0};       // m/s²
  double surfaceTension = 0.0;  // σ, N/m
  double influenceRatio = 0.0;  // interaction.influence_ratio (scenes with objects)
};

}  // namespace sph
