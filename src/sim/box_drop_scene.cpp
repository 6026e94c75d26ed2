#include "sph/box_drop_scene.hpp"

#include <algorithm>
#include <cmath>

namespace sph {

namespace {

// nx · ny · nx = particles with nx ≥ ny as close to a cube as the count allows.
void blockShape(int particles, int& nx, int& ny) {
  const int cube = static_cast<int>(std::ceil(std::cbrt(double(particles)) - 1e-9));
  for (int x = cube; x <= 2 * cube; ++x) {
    if (particles % (x * x) == 0) {
      nx = x;
      ny = particles / (x * x);
      return;
    }
  }
  nx = cube;
  ny = std::max(1, static_cast<int>(std::lround(double(particles) / (cube * cube))));
}

}  // namespace

Scene boxDropScene(int particles) {
  int nx = 0, ny = 0;
  blockShape(particles, nx, ny);
  const double d = 0.01;
  const double width = 2.0 * nx * d, height = 2.0 * std::max(nx, ny) * d;
  Scene s;
  s.name = "box_drop";
  s.sourcePath = "box_drop (built in)";
  s.domain.box = {{0, 0, 0}, {width, height, width}};
  s.domain.dampedBox = true;
  s.domain.damping = 0.5;
  s.fluid.spacing = d;
  s.fluid.kernel = KernelKind::Muller;
  s.fluid.viscosityModel = ViscosityModel::Artificial;
  s.fluid.viscosity = 0.05;
  const double x0 = 0.5 * (width - nx * d);
  FluidBlock block;
  block.box = AxisBox{{x0, height - ny * d, x0}, {x0 + nx * d, height, x0 + nx * d}};
  s.fluid.blocks.push_back(block);
  s.time.duration = 1.0;
  s.output.format = FrameFormat::None;
  return s;
}

}  // namespace sph
