#include "backend/cpu_parallel.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/stages.hpp"
#include "sph/core/momentum.hpp"

namespace sph::fluid {

namespace {

template <class Kernels>
void forcePass(FluidParticles& fluid, const Grid& grid, const BoundaryParticles& boundary,
               const FluidParameters& params, Kernels kernels) {
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const GridSpec wallGrid = boundary.grid;
  const std::uint32_t* wallCellStart = boundary.cellStart.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const float* density = fluid.density.data();
  const float* pressure = fluid.pressure.data();
  const Vec4* wall = boundary.position.data();
  Vec4* acceleration = fluid.acceleration.data();
  const std::uint32_t* id = fluid.id.data();
  const Vec4* external = fluid.externalById.size() ? fluid.externalById.data() : nullptr;
  const FluidParameters p = params;
  const float h2 = p.h * p.h;
  const bool symmetric = p.pressureForm == PressureForm::Symmetric;
  const bool artificial = p.viscosityModel == ViscosityModel::Artificial;

  backend::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 xi = xyz(position[i]);
        const Vec3 vi = xyz(velocity[i]);
        const float rhoI = density[i];
        const float pI = pressure[i];
        Vec3 a = external ? p.gravity + xyz(external[id[i]]) : p.gravity;
        Vec3 colourGradient{0.0f, 0.0f, 0.0f};
        float colourLaplacian = 0.0f;

        forEachNeighbor(spec, cellStart, xi, [&](std::uint32_t j) {
          const Vec3 rij = xi - xyz(position[j]);
          const float r2 = lengthSquared(rij);
          if (r2 >= h2 || j == i) return;
          const float r = realSqrt(r2);
          const float rhoJ = density[j];
          const Vec3 gradW = rij * kernels.gradFactor(r);
          a += symmetric ? pressureAccelerationSymmetric(p.mass, pI, rhoI, pressure[j], rhoJ, gradW)
                         : pressureAccelerationPaper(p.mass, pI, rhoI, pressure[j], rhoJ, gradW);
          const Vec3 vij = vi - xyz(velocity[j]);
          a += artificial ? artificialViscosityAcceleration(p.viscosity, p.soundSpeed, p.h, p.mass,
                                                            rhoI, rhoJ, vij, rij, r2, gradW)
                          : mullerViscosityAcceleration(p.viscosity, p.mass, rhoI, rhoJ, vij,
                                                        kernels.laplacian(r));
          const float volumeJ = p.mass / rhoJ;  // seed 1 eqs. 11-12 with C_j = 1
          colourGradient += rij * (volumeJ * kernels.colourGradFactor(r));
          colourLaplacian += volumeJ * kernels.colourLaplacian(r);
        });

        if (wallCellStart != nullptr) {
          forEachNeighbor(wallGrid, wallCellStart, xi, [&](std::uint32_t b) {
            const Vec3 rib = xi - xyz(wall[b]);
            const float r2 = lengthSquared(rib);
            if (r2 >= h2 || r2 <= 0.0f) return;
            const float r = realSqrt(r2);
            const float volumeB = wall[b].w;
            const float massB = p.restDensity * volumeB;
            const Vec3 gradW = rib * kernels.gradFactor(r);
            const float pB = wallPressure(pI, rhoI, p.gravity, -rib, p.clampNegativePressure);
            a += boundaryPressureAcceleration(massB, pI, rhoI, pB, gradW);
            if (p.wallFriction > 0.0f) {
              const Vec3 friction =
                  artificial
                      ? artificialViscosityAcceleration(p.viscosity, p.soundSpeed, p.h, massB, rhoI,
                                                        p.restDensity, vi, rib, r2, gradW)
                      : mullerViscosityAcceleration(p.viscosity, massB, rhoI, p.restDensity, vi,
                                                    kernels.laplacian(r));
              a += friction * p.wallFriction;
            }
            // Walls are not empty space: fluid against a wall is not free surface.
            colourGradient += rib * (volumeB * kernels.colourGradFactor(r));
          });
        }

        const float normalLength = length(colourGradient);
        if (p.surfaceTension > 0.0f && normalLength > p.surfaceThreshold) {
          // Müller et al. 2003 eq. 19: f = -σ ∇²c n/|n|, as an acceleration.
          a -= colourGradient * (p.surfaceTension * colourLaplacian / (normalLength * rhoI));
        }
        acceleration[i] = makeVec4(a, normalLength);
      });
}

}  // namespace

void computeForces(FluidParticles& fluid, const Grid& grid, const BoundaryParticles& boundary,
                   const FluidParameters& params) {
  withKernels(params, [&](auto kernels) { forcePass(fluid, grid, boundary, params, kernels); });
}

}  // namespace sph::fluid
