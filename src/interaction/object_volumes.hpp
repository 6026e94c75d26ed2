// The volume ψ_k = 1 / Σ_l W_kl of each object particle as a boundary particle of the fluid
// (Akinci et al. 2012, eq. 4: a particle of a sparse or curved sheet stands for as much as one
// of a dense flat one), summed over the objects' particles, itself included. Host code, kept
// apart from the backends' passes so that nvcc compiles none of it.
#pragma once

#include <cstdint>
#include <vector>

#include "fluid/parameters.hpp"
#include "sph/core/grid.hpp"
#include "sph/core/vec.hpp"

namespace sph::interaction {

// position in ObjectParticles order, sorted into `grid` by `cellStart` (cells at least h).
// Returns xyz: the position, w: ψ_k.
std::vector<Vec4> withObjectVolumes(const std::vector<Vec4>& position,
                                    const std::vector<std::uint32_t>& cellStart,
                                    const GridSpec& grid, const fluid::FluidParameters& params);

}  // namespace sph::interaction
