// Stage (when the engine publishes, with boundary coupling): the objects' surface particles as
// boundary particles of the fluid (Akinci et al. 2012), in the order and on the grid of the
// contact pass's ObjectParticles (whose cells are then at least h), each with its volume
// ψ_k = 1 / Σ_l W_kl over the objects' particles (Akinci's eq. 4: a particle of a sparse or
// curved sheet stands for as much as one of a dense flat one). Built on the host, like
// ObjectParticles, and handed to backend B.
//
// A sheet of such particles holds the fluid's first layer about a spacing off, as one more
// layer of fluid would, where a wall holds it half a spacing off: the fluid ends half a
// spacing past the object's surface, and a floating box sat 21 % too high. Moving the sheet
// that half spacing away from the fluid put the box 15 % too low, fluid leaking into it
// through its edges.
#pragma once

#include <cstdint>
#include <vector>

#include "fluid/particles.hpp"
#include "fluid/prepare_boundary.hpp"
#include "interaction/object_particles.hpp"
#include "interaction/object_volumes.hpp"

namespace sph::interaction {

// position and velocity in ObjectParticles order (w of the position: the radius), ψ_k from
// object_volumes.hpp.
template <class B>
void prepareObjectBoundary(fluid::BoundaryParticles<B>& boundary, const std::vector<Vec4>& position,
                           const std::vector<Vec4>& velocity,
                           const std::vector<std::uint32_t>& cellStart, const GridSpec& grid,
                           const fluid::FluidParameters& params) {
  const std::size_t n = position.size();
  boundary.count = n;
  if (n == 0) return;
  boundary.grid = grid;
  const std::vector<Vec4> withVolume = withObjectVolumes(position, cellStart, grid, params);
  std::vector<std::uint32_t> twin(n);
  for (std::size_t k = 0; k < n; ++k) twin[k] = std::uint32_t(k);
  B::upload(boundary.position, withVolume.data(), n);
  B::upload(boundary.id, twin.data(), n);
  B::upload(boundary.cellStart, cellStart.data(), cellStart.size());
  std::vector<Vec4> moving(n + fluid::kBatchPadding, Vec4{0.0f, 0.0f, 0.0f, 0.0f});
  for (std::size_t k = 0; k < n; ++k) moving[k] = makeVec4(xyz(velocity[k]), 0.0f);
  B::upload(boundary.velocity, moving.data(), moving.size());
  fluid::uploadBatchArrays(boundary, withVolume);
}

}  // namespace sph::interaction
