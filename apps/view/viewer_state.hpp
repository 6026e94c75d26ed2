// What the viewer's window, panel and keys share between display frames.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "particle_renderer.hpp"
#include "probe_readings.hpp"
#include "sph/simulation.hpp"

namespace sph::view {

struct ViewerState {
  bool paused = false;
  bool stepOnce = false;        // one step, then paused
  bool resetRequested = false;  // rebuild the simulation from the scene
  bool grabbable = false;       // the scene has a kinematic object ctrl + drag can move
  render::DrawSettings draw;
  std::string message;     // the last error, shown in the panel until the next reset
  std::string fluidPath;   // how the fluid reaches the renderer (FluidFeed::path)
  LiveParameters editing;  // the panel's fields while the user edits them
  ProbeReadings probes;    // the scene's probes, as sampled
  // The kinematic object last grabbed (or the scene's first): the force on it, |fluid +
  // contact| in N, one value a display frame, oldest first.
  bool watching = false;
  std::size_t watched = 0;
  std::string watchedName;
  std::vector<float> watchedForce;

  // Smoothed over the last frames, for steady figures.
  StepProfile profile;          // ms per step, by stage
  double realTimeFactor = 0.0;  // simulated seconds per wall second
  double framesPerSecond = 0.0;
};

// Exponential smoothing of the figures shown, weight `w` on the newest.
void smooth(StepProfile& into, const StepProfile& latest, double w);

}  // namespace sph::view
