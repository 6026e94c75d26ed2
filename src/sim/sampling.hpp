// Lattice sampling of the scene's geometry into particles.
#pragma once

#include <vector>

#include "sph/core/vec.hpp"
#include "sph/scene.hpp"

namespace sph::sim {

// Particles at the centres of the cubic cells of edge `spacing` that fill the box; the box's
// faces are the fluid's faces.
std::vector<Vec3> sampleBlock(const AxisBox& box, double spacing);

// `tank.layers` layers of particles outside the tank's inner faces, on the same lattice as the
// fluid, open on the side gravity points away from unless closed.
std::vector<Vec3> sampleTank(const WallTank& tank, double spacing, const Vec3d& gravity);

// The axis gravity acts along (y when there is none).
int upAxisOf(const Vec3d& gravity);

}  // namespace sph::sim
