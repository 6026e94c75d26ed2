// Stage: all forces in one pass (Meteer 2011, Algorithm 2): pressure (unless the incompressible
// solver gives it), viscosity, surface tension, gravity and external accelerations. Reads position,
// velocity, pressureState, the neighbour lists, the walls and externalById. Writes acceleration (w:
// 0; |∇c| for the surface flags is measured when a frame is taken, measure_surface.hpp). The colour
// field is summed only for surface tension, which needs it: it is a fifth of the pass.
#pragma once

#include "fluid/forces_batched.hpp"
#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "sph/core/read_only.hpp"

namespace sph::fluid {

namespace detail {

template <class B, class Options, class Kernels>
void forcePass(FluidParticles<B>& fluid, const Grid<B>& grid, const BoundaryParticles<B>& boundary,
               const BoundaryParticles<B>& objects, const FluidParameters& params,
               Kernels kernels) {
  const NeighborLists lists = neighborLists(fluid, grid);
  const WallCells walls = wallCells(boundary);
  const WallCells objectCells = wallCells(objects);
  const Vec4* object = objects.position.data();  // w: volume ψ_k
  const Vec4* objectVelocity = objects.velocity.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const Vec4* state = fluid.pressureState.data();
  const Vec4* wall = boundary.position.data();  // w: volume ψ_b
  Vec4* acceleration = fluid.acceleration.data();
  const std::uint32_t* id = fluid.id.data();
  const Vec4* external = fluid.externalById.size() ? fluid.externalById.data() : nullptr;
  const FluidParameters p = params;
  const float h2 = p.h * p.h;

  const ForceConstants<float, Vec3, Kernels> constants(p, kernels);
  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 xi = xyz(position[i]);
        const bool seam = nearSeam(p.periodic, xi);
        const ForceTerms<float, Vec3, Options, Kernels> terms(
            constants, unpackPressureState(state[i]), xyz(velocity[i]));
        ForceSums<float, Vec3> sums;
        forEachListedNeighbor(lists, i, xi, [&](std::uint32_t j) {
          const Vec3 rij = separation(p.periodic, seam, xi, xyz(readOnly(position + j)));
          const float r2 = lengthSquared(rij);
          if (r2 >= h2) return;
          const PressureState sj = unpackPressureState(readOnly(state + j));
          terms.addFluid(sums, makePair(rij, r2, true, h2), xyz(readOnly(velocity + j)),
                         pressureTerm<Options>(sj), sj.density);
        });
        forEachWallNeighbor(walls, xi, [&](std::uint32_t b) {
          const Vec4 xb = readOnly(wall + b);
          const Vec3 rib = xi - xyz(xb);
          const float r2 = lengthSquared(rib);
          if (r2 >= h2 || r2 <= 0.0f) return;
          terms.addWall(sums, makePair(rib, r2, true, h2), xb.w);
        });
        forEachWallNeighbor(objectCells, xi, [&](std::uint32_t k) {
          const Vec4 xk = readOnly(object + k);
          const Vec3 rik = xi - xyz(xk);
          const float r2 = lengthSquared(rik);
          if (r2 >= h2 || r2 <= 0.0f) return;
          terms.addObject(sums, makePair(rik, r2, true, h2), xk.w,
                          xyz(readOnly(objectVelocity + k)));
        });
        const Vec3 extra = external ? xyz(external[id[i]]) : Vec3{0.0f, 0.0f, 0.0f};
        acceleration[i] = makeVec4(terms.total(sums, extra), 0.0f);
      });
}

template <class B, class Options>
void forcePassWithKernels(FluidParticles<B>& fluid, const Grid<B>& grid,
                          const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                          const FluidParameters& params, [[maybe_unused]] NeighborWalk walk) {
  withKernels(params, [&](auto kernels) {
#if !defined(__CUDACC__)
    if constexpr (B::kBatches) {
      if (walk == NeighborWalk::Batched) {
        forcePassBatched<Options>(fluid, grid, boundary, objects, params, kernels);
        return;
      }
    }
#endif
    forcePass<B, Options>(fluid, grid, boundary, objects, params, kernels);
  });
}

template <class B, PressureForm kForm, ViscosityModel kViscosity, bool kPressure>
void forcePassWithTension(FluidParticles<B>& fluid, const Grid<B>& grid,
                          const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                          const FluidParameters& params, NeighborWalk walk) {
  if (params.surfaceTension > 0.0f) {
    forcePassWithKernels<B, ForceOptions<kForm, kViscosity, true, kPressure>>(
        fluid, grid, boundary, objects, params, walk);
  } else {
    forcePassWithKernels<B, ForceOptions<kForm, kViscosity, false, kPressure>>(
        fluid, grid, boundary, objects, params, walk);
  }
}

template <class B, PressureForm kForm, bool kPressure = true>
void forcePassWithViscosity(FluidParticles<B>& fluid, const Grid<B>& grid,
                            const BoundaryParticles<B>& boundary,
                            const BoundaryParticles<B>& objects, const FluidParameters& params,
                            NeighborWalk walk) {
  if (params.viscosityModel == ViscosityModel::Artificial) {
    forcePassWithTension<B, kForm, ViscosityModel::Artificial, kPressure>(fluid, grid, boundary,
                                                                          objects, params, walk);
  } else {
    forcePassWithTension<B, kForm, ViscosityModel::Muller, kPressure>(fluid, grid, boundary,
                                                                      objects, params, walk);
  }
}

}  // namespace detail

// objects: the objects' particles as boundary particles (interaction.coupling "boundary"), or
// none.
template <class B>
void computeForces(FluidParticles<B>& fluid, const Grid<B>& grid,
                   const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                   const FluidParameters& params, NeighborWalk walk) {
  if (!params.pressureForces) {
    detail::forcePassWithViscosity<B, PressureForm::Symmetric, false>(fluid, grid, boundary,
                                                                      objects, params, walk);
  } else if (params.pressureForm == PressureForm::Symmetric) {
    detail::forcePassWithViscosity<B, PressureForm::Symmetric>(fluid, grid, boundary, objects,
                                                               params, walk);
  } else {
    detail::forcePassWithViscosity<B, PressureForm::Paper>(fluid, grid, boundary, objects, params,
                                                           walk);
  }
}

}  // namespace sph::fluid
