// Time step conditions for explicit weakly-compressible SPH (Monaghan 1992; Morris 1997).
#pragma once

#include <algorithm>
#include <cmath>

namespace sph {

// Sound must not cross more than a fraction of h per step.
inline double cflTimeStep(double cfl, double h, double soundSpeed, double maxSpeed) {
  return cfl * h / (soundSpeed + maxSpeed);
}

// An incompressible solver's step follows the flow: nothing crosses more than cfl·h in a step.
inline double flowTimeStep(double cfl, double h, double maxSpeed) {
  return maxSpeed > 0.0 ? cfl * h / maxSpeed : HUGE_VAL;
}

// A particle must not move more than a fraction of h under its acceleration.
inline double forceTimeStep(double factor, double h, double maxAcceleration) {
  return maxAcceleration > 0.0 ? factor * std::sqrt(h / maxAcceleration) : HUGE_VAL;
}

// Explicit diffusion is stable below h² / (2 d ν); `factor` holds the margin. Against a wall
// the viscous term is scaled by the wall friction (2 for no-slip, the wall taking the opposite
// of the fluid's velocity), and so is the diffusion there: a plane Poiseuille channel at
// wall_friction 2 grew an instability at 1.3 ms steps that its 0.98 ms bound holds off.
inline double viscousTimeStep(double factor, double h, double kinematicViscosity,
                              double wallFriction = 1.0) {
  const double diffusivity = kinematicViscosity * std::max(1.0, wallFriction);
  return diffusivity > 0.0 ? factor * h * h / diffusivity : HUGE_VAL;
}

// What bounds a run's steps, fixed until a live parameter changes (sim/calibration fills it).
struct StepLimits {
  bool followsFlow = false;  // incompressible: the step follows the flow, no sound speed bounds it
  double cfl = 0.4;
  double h = 0.0;
  double soundSpeed = 0.0;
  double forceFactor = 0.25;
  double viscousFactor = 0.125;
  double kinematicViscosity = 0.0;
  double wallFriction = 1.0;
  double maxDt = HUGE_VAL;
};

// The longest step every bound allows at the fluid's largest speed and acceleration;
// `otherBound`: what else limits it (the objects').
inline double longestStep(const StepLimits& l, double maxSpeed, double maxAcceleration,
                          double otherBound = HUGE_VAL) {
  const double motion = l.followsFlow ? flowTimeStep(l.cfl, l.h, maxSpeed)
                                      : cflTimeStep(l.cfl, l.h, l.soundSpeed, maxSpeed);
  return std::min({motion, forceTimeStep(l.forceFactor, l.h, maxAcceleration),
                   viscousTimeStep(l.viscousFactor, l.h, l.kinematicViscosity, l.wallFriction),
                   otherBound, l.maxDt});
}

// A spring of stiffness k (scaled at most by `peakScale`) on a mass m oscillates at
// ω = sqrt(k peakScale / m); an explicit step of 1/ω resolves it (contacts: Meteer 2011, §8.3).
inline double springTimeStep(double mass, double stiffness, double peakScale) {
  return stiffness > 0.0 ? std::sqrt(mass / (stiffness * peakScale)) : HUGE_VAL;
}

// Nothing moving at `speed` travels more than `distance` in a step: no tunnelling (§8.3).
inline double travelTimeStep(double distance, double speed) {
  return speed > 0.0 ? distance / speed : HUGE_VAL;
}

// Speed of sound about ten times the largest expected speed keeps density errors near 1 %.
inline double soundSpeedForMaxSpeed(double maxExpectedSpeed) {
  return 10.0 * maxExpectedSpeed;
}

// Largest speed of a column of height H falling freely: sqrt(2 g H).
inline double freeFallSpeed(double gravity, double height) {
  return std::sqrt(2.0 * std::max(gravity, 0.0) * std::max(height, 0.0));
}

}  // namespace sph
