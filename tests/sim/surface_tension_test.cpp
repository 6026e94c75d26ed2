// Surface tension from the colour field (Müller et al. 2003) pulls a cube of fluid in zero
// gravity toward a sphere: its corners come in; without surface tension they do not.
#include <gtest/gtest.h>

#include <cmath>

#include "sph/simulation.hpp"

namespace sph {
namespace {

Scene floatingCube(double surfaceTension) {
  Scene s;
  s.sourcePath = "floating cube (test)";
  s.gravity = {0, 0, 0};
  s.calibration.speedOfSound = 5.0;
  s.fluid.spacing = 0.005;
  s.fluid.viscosityModel = ViscosityModel::Artificial;
  s.fluid.viscosity = 0.5;
  s.fluid.surfaceTension = surfaceTension;
  s.domain.box = {{-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}};
  s.fluid.blocks.push_back({{{-0.03, -0.03, -0.03}, {0.03, 0.03, 0.03}}, {0, 0, 0}, false, ""});
  return s;
}

// The largest distance of a particle from the fluid's centre: a cube's corner, √3 × half-edge.
double largestRadius(const Simulation& sim) {
  const ParticleFrame f = sim.frame(false);
  double c[3] = {0, 0, 0};
  for (std::size_t i = 0; i < f.size(); ++i)
    for (int a = 0; a < 3; ++a) c[a] += f.position[3 * i + a] / double(f.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    double r2 = 0.0;
    for (int a = 0; a < 3; ++a) r2 += std::pow(f.position[3 * i + a] - c[a], 2);
    largest = std::max(largest, std::sqrt(r2));
  }
  return largest;
}

TEST(SurfaceTension, PullsACubeTowardASphere) {
  Simulation withTension(floatingCube(0.1));
  Simulation without(floatingCube(0.0));
  const double corner = largestRadius(withTension);
  withTension.advanceTo(0.1);
  without.advanceTo(0.1);
  EXPECT_GT(withTension.stats().surfaceCount, 0u);
  EXPECT_LT(largestRadius(withTension), 0.95 * corner) << "corners pulled in";
  EXPECT_GT(largestRadius(without), 0.98 * corner) << "without tension the cube keeps its corners";
}

}  // namespace
}  // namespace sph
