#include "backend/cpu_parallel.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/stages.hpp"
#include "sph/core/eos.hpp"

namespace sph::fluid {

namespace {

template <class Kernels>
void densityPass(FluidParticles& fluid, const Grid& grid, const BoundaryParticles& boundary,
                 const FluidParameters& params, Kernels kernels) {
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const GridSpec wallGrid = boundary.grid;
  const std::uint32_t* wallCellStart = boundary.cellStart.data();
  const Vec4* position = fluid.position.data();
  const Vec4* wall = boundary.position.data();
  float* density = fluid.density.data();
  float* pressure = fluid.pressure.data();
  const FluidParameters p = params;

  backend::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 xi = xyz(position[i]);
        float sum = 0.0f;  // seed 1 eq. 4, self included
        forEachNeighbor(spec, cellStart, xi, [&](std::uint32_t j) {
          sum += kernels.W(lengthSquared(xi - xyz(position[j])));
        });
        float wallSum = 0.0f;  // Akinci et al. 2012 eq. 6: walls count with mass ρ0 ψ_b
        if (wallCellStart != nullptr) {
          forEachNeighbor(wallGrid, wallCellStart, xi, [&](std::uint32_t b) {
            wallSum += wall[b].w * kernels.W(lengthSquared(xi - xyz(wall[b])));
          });
        }
        const float rho = p.mass * sum + p.restDensity * wallSum;
        density[i] = rho;
        pressure[i] =
            pressureFromDensity(p.eos, rho, p.restDensity, p.stiffness, p.clampNegativePressure);
      });
}

}  // namespace

void computeDensityAndPressure(FluidParticles& fluid, const Grid& grid,
                               const BoundaryParticles& boundary, const FluidParameters& params) {
  withKernels(params, [&](auto kernels) { densityPass(fluid, grid, boundary, params, kernels); });
}

}  // namespace sph::fluid
