// Stage: all forces in one pass (seed 1 Algorithm 2): pressure, viscosity, surface tension,
// gravity and external accelerations. Reads position, velocity, pressureState, the neighbour
// lists, the walls and externalById. Writes acceleration (w: 0; |∇c| for the surface flags is
// measured when a frame is taken, measure_surface.hpp). The colour field is summed only for
// surface tension, which needs it: it is a fifth of the pass.
#pragma once

#include "fluid/forces_batched.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/parameters.hpp"
#include "fluid/particles.hpp"
#include "sph/core/momentum.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

namespace detail {

// The scene's choices as compile-time constants, so the neighbour loop has no branch on them.
template <PressureForm kForm, ViscosityModel kViscosity, bool kSurfaceTension>
struct ForceOptions {
  static constexpr PressureForm form = kForm;
  static constexpr ViscosityModel viscosity = kViscosity;
  static constexpr bool surfaceTension = kSurfaceTension;
};

template <class B, class Options, class Kernels>
void forcePass(FluidParticles<B>& fluid, const Grid<B>& grid, const BoundaryParticles<B>& boundary,
               const FluidParameters& params, Kernels kernels) {
  constexpr bool kSymmetric = Options::form == PressureForm::Symmetric;
  constexpr bool kArtificial = Options::viscosity == ViscosityModel::Artificial;
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const GridSpec wallGrid = boundary.grid;
  const std::uint32_t* wallCellStart = boundary.cellStart.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const Vec4* state = fluid.pressureState.data();  // p/ρ², 1/ρ, p, ρ
  const Vec4* wall = boundary.position.data();
  Vec4* acceleration = fluid.acceleration.data();
  const std::uint32_t* id = fluid.id.data();
  const Vec4* external = fluid.externalById.size() ? fluid.externalById.data() : nullptr;
  const FluidParameters p = params;
  const float h2 = p.h * p.h;
  const std::uint32_t stride = fluid.neighborStride;
  const std::uint32_t* neighbors = fluid.neighbors.data();
  const std::uint32_t* neighborCount = fluid.neighborCount.data();

  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 xi = xyz(position[i]);
        const Vec3 vi = xyz(velocity[i]);
        const Vec4 si = state[i];
        const float pI = si.z, rhoI = si.w;
        Vec3 a = external ? p.gravity + xyz(external[id[i]]) : p.gravity;
        Vec3 colourGradient{0.0f, 0.0f, 0.0f};
        float colourLaplacian = 0.0f;

        auto pair = [&](std::uint32_t j) {
          const Vec3 rij = xi - xyz(readOnly(position + j));
          const float r2 = lengthSquared(rij);
          if (r2 >= h2 || j == i) return;
          const float r = realSqrt(r2);
          const Vec4 sj = readOnly(state + j);
          const Vec3 gradW = rij * kernels.gradFactor(r);
          if (kSymmetric) {
            a += pressureAccelerationSymmetric(p.mass, si.x, sj.x, gradW);
          } else {
            a += pressureAccelerationPaper(p.mass, pI, si.y, sj.z, sj.y, gradW);
          }
          const Vec3 vij = vi - xyz(readOnly(velocity + j));
          if (kArtificial) {
            a += artificialViscosityAcceleration(p.viscosity, p.soundSpeed, p.h, p.mass, rhoI, sj.w,
                                                 vij, rij, r2, gradW);
          } else {
            a += mullerViscosityAcceleration(p.viscosity, p.mass, rhoI, sj.w, vij,
                                             kernels.laplacian(r));
          }
          if (Options::surfaceTension) {
            const float volumeJ = p.mass * sj.y;  // seed 1 eqs. 11-12 with C_j = 1
            colourGradient += rij * (volumeJ * kernels.colourGradFactor(r));
            colourLaplacian += volumeJ * kernels.colourLaplacian(r);
          }
        };
        const std::uint32_t count = neighborCount[i];
        if (count != kNeighborOverflow) {
          const std::uint32_t* list = neighbors + i * stride;
          for (std::uint32_t k = 0; k < count; ++k) pair(readOnly(list + k));
        } else {
          forEachNeighbor(spec, cellStart, xi, pair);
        }

        if (wallCellStart != nullptr) {
          forEachNeighbor(wallGrid, wallCellStart, xi, [&](std::uint32_t b) {
            const Vec4 xb = readOnly(wall + b);
            const Vec3 rib = xi - xyz(xb);
            const float r2 = lengthSquared(rib);
            if (r2 >= h2 || r2 <= 0.0f) return;
            const float r = realSqrt(r2);
            const float volumeB = xb.w;
            const float massB = p.restDensity * volumeB;
            const Vec3 gradW = rib * kernels.gradFactor(r);
            const float pB = wallPressure(pI, rhoI, p.gravity, -rib, p.clampNegativePressure);
            a += boundaryPressureAcceleration(massB, pI, rhoI, pB, gradW);
            if (p.wallFriction > 0.0f) {
              const Vec3 friction =
                  kArtificial
                      ? artificialViscosityAcceleration(p.viscosity, p.soundSpeed, p.h, massB, rhoI,
                                                        p.restDensity, vi, rib, r2, gradW)
                      : mullerViscosityAcceleration(p.viscosity, massB, rhoI, p.restDensity, vi,
                                                    kernels.laplacian(r));
              a += friction * p.wallFriction;
            }
            // Walls are not empty space: fluid against a wall is not free surface.
            if (Options::surfaceTension)
              colourGradient += rib * (volumeB * kernels.colourGradFactor(r));
          });
        }

        if (Options::surfaceTension) {
          const float normalLength = length(colourGradient);
          if (normalLength > p.surfaceThreshold) {
            // Müller et al. 2003 eq. 19: f = -σ ∇²c n/|n|, as an acceleration.
            a -= colourGradient * (p.surfaceTension * colourLaplacian / (normalLength * rhoI));
          }
        }
        acceleration[i] = makeVec4(a, 0.0f);
      });
}

template <class B, class Options>
void forcePassWithKernels(FluidParticles<B>& fluid, const Grid<B>& grid,
                          const BoundaryParticles<B>& boundary, const FluidParameters& params) {
  withKernels(params, [&](auto kernels) {
#if !defined(__CUDACC__)
    if constexpr (B::kBatches) {
      if (backend::batchedPasses()) {
        forcePassBatched<Options>(fluid, grid, boundary, params, kernels);
        return;
      }
    }
#endif
    forcePass<B, Options>(fluid, grid, boundary, params, kernels);
  });
}

template <class B, PressureForm kForm, ViscosityModel kViscosity>
void forcePassWithTension(FluidParticles<B>& fluid, const Grid<B>& grid,
                          const BoundaryParticles<B>& boundary, const FluidParameters& params) {
  if (params.surfaceTension > 0.0f) {
    forcePassWithKernels<B, ForceOptions<kForm, kViscosity, true>>(fluid, grid, boundary, params);
  } else {
    forcePassWithKernels<B, ForceOptions<kForm, kViscosity, false>>(fluid, grid, boundary, params);
  }
}

template <class B, PressureForm kForm>
void forcePassWithViscosity(FluidParticles<B>& fluid, const Grid<B>& grid,
                            const BoundaryParticles<B>& boundary, const FluidParameters& params) {
  if (params.viscosityModel == ViscosityModel::Artificial) {
    forcePassWithTension<B, kForm, ViscosityModel::Artificial>(fluid, grid, boundary, params);
  } else {
    forcePassWithTension<B, kForm, ViscosityModel::Muller>(fluid, grid, boundary, params);
  }
}

}  // namespace detail

template <class B>
void computeForces(FluidParticles<B>& fluid, const Grid<B>& grid,
                   const BoundaryParticles<B>& boundary, const FluidParameters& params) {
  if (params.pressureForm == PressureForm::Symmetric) {
    detail::forcePassWithViscosity<B, PressureForm::Symmetric>(fluid, grid, boundary, params);
  } else {
    detail::forcePassWithViscosity<B, PressureForm::Paper>(fluid, grid, boundary, params);
  }
}

}  // namespace sph::fluid
