#include "interaction/object_volumes.hpp"

#include "backend/cpu_parallel.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"

namespace sph::interaction {

std::vector<Vec4> withObjectVolumes(const std::vector<Vec4>& position,
                                    const std::vector<std::uint32_t>& cellStart,
                                    const GridSpec& grid, const fluid::FluidParameters& params) {
  const std::size_t n = position.size();
  std::vector<Vec4> out(n);
  const float h2 = params.h * params.h;
  fluid::withKernels(params, [&](auto kernels) {
    backend::forEach(n, [&](std::size_t k) {
      const Vec3 xk = xyz(position[k]);
      float density = 0.0f;  // Σ_l W_kl, itself included
      fluid::forEachNeighbor(grid, cellStart.data(), xk, [&](std::uint32_t l) {
        const float r2 = lengthSquared(xk - xyz(position[l]));
        if (r2 < h2) density += kernels.W(r2);
      });
      out[k] = makeVec4(xk, 1.0f / density);
    });
  });
  return out;
}

}  // namespace sph::interaction
