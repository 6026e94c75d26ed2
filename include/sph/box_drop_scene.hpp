// The benchmark scene of Meteer 2011, §10: N particles dropped in a box the size of the grid.
#pragma once

#include "sph/scene.hpp"

namespace sph {

// A block of about `particles` fluid particles (exactly, when it factors as nx·ny·nx) at the
// top of a damped box twice its size, Müller kernels, h = 2d.
Scene boxDropScene(int particles);

}  // namespace sph
