// Lattice sampling of the scene's geometry into particles.
#pragma once

#include <vector>

#include "sph/core/vec.hpp"
#include "sph/scene.hpp"

namespace sph::sim {

// Particles at the centres of the cubic cells of edge `spacing` that fill the box; the box's
// faces are the fluid's faces.
std::vector<Vec3> sampleBlock(const AxisBox& box, double spacing);

// `layers` layers of particles outside the tank's inner faces `inner`, on the same lattice as
// the fluid, open on the side gravity points away from unless closed.
std::vector<Vec3> sampleTank(const AxisBox& inner, int layers, bool closed, double spacing,
                             const Vec3d& gravity);

// Moves the points of a block resting under gravity to the compression of hydrostatic
// equilibrium: at depth z below the block's top the density is ρ0 (1 + g z / c0²) to first
// order for every equation of state, so a column of lattice spacing d shortens to
// z' = (c0²/g) ln(1 + g z / c0²).
void compressHydrostatically(std::vector<Vec3>& points, const AxisBox& block, const Vec3d& gravity,
                             double soundSpeed);

// The density each point of a block stands for, at rest: ρ0 (1 + g z / c0²) at depth z (of the
// uncompressed lattice) for a hydrostatic block, whose points compressHydrostatically has
// moved; ρ0 for any other. What continuity density starts from, where a kernel sum would read
// low at the free surface.
std::vector<float> restingDensities(const std::vector<Vec3>& points, const AxisBox& block,
                                    bool hydrostatic, const Vec3d& gravity, double soundSpeed,
                                    double restDensity);

// The axis gravity acts along (y when there is none).
int upAxisOf(const Vec3d& gravity);

}  // namespace sph::sim
