// `sph view`: a window that runs the simulation and draws it at display rate (GLFW, OpenGL 3.3
// core, Dear ImGui), through the same renderer as `sph render`.
#pragma once

#include <string>

#include "sph/scene.hpp"
#include "sph/simulation.hpp"

namespace sph::view {

struct ViewOptions {
  SimulationOptions simulation;
  int width = 1280;
  int height = 720;
  std::string colour = "kind";  // kind, density, pressure, speed or surface
  // liquid or particles; empty: the scene's render.look, particles when colouring by a quantity
  std::string look;
  bool objectSurfaces = true;  // objects drawn as their surfaces; false: as particles
  bool probe = true;           // a kinematic sphere the mouse drags through the fluid
  // For scripts and tests: close after this many display frames (0: when the window closes),
  // writing the last one to `screenshot` (a PNG) when given.
  int frames = 0;
  std::string screenshot;
};

// Runs until the window closes (or `frames` are shown). Throws InputError on bad input and
// std::runtime_error when no window can be opened (no display: see docs/rendering.md).
void runViewer(const Scene& scene, const ViewOptions& options);

}  // namespace sph::view
