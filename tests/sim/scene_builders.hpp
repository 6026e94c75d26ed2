// Small scenes built in code for the physics tests: each runs in seconds.
#pragma once

#include "sph/scene.hpp"

namespace sph::testing {

// A water column of height `height` at rest in a tank `width` wide, 2 wall layers.
inline Scene restingTank(double spacing, double width, double height) {
  Scene s;
  s.name = "resting_tank";
  s.sourcePath = "resting_tank (test)";
  s.fluid.spacing = spacing;
  s.fluid.viscosity = 0.1;
  s.fluid.wallFriction = 1.0;
  s.domain.box = {{-0.1, -0.1, -0.1}, {width + 0.1, 2.0 * height + 0.1, width + 0.1}};
  s.fluid.blocks.push_back({{{0, 0, 0}, {width, height, width}}, {0, 0, 0}, false, ""});
  s.walls.push_back(WallDesc::tank({{0, 0, 0}, {width, 1.25 * height, width}}, 2, false));
  return s;
}

// Two blocks flying at each other in empty space, no gravity, no walls.
inline Scene collidingBlocks(PressureForm form) {
  Scene s;
  s.name = "colliding_blocks";
  s.sourcePath = "colliding_blocks (test)";
  s.gravity = {0, 0, 0};
  s.fluid.spacing = 0.01;
  s.fluid.pressureForm = form;
  s.fluid.viscosity = 0.1;
  s.domain.box = {{-1, -1, -1}, {1, 1, 1}};
  s.fluid.blocks.push_back({{{-0.12, 0, 0}, {-0.02, 0.1, 0.08}}, {1.0, 0.2, 0}, false, ""});
  s.fluid.blocks.push_back({{{0.0, 0.03, 0.02}, {0.06, 0.09, 0.1}}, {-1.5, 0, 0.3}, false, ""});
  return s;
}

}  // namespace sph::testing
