// Stage (boundary coupling, after the density solve): the fluid's force on each object
// particle, the opposite of what the incompressible solver's two solves applied to the fluid
// through it. A solve pushes fluid particle i off boundary particle k with the mirrored K_i
// (Akinci et al. 2012): m a_ik = -2 m ρ0 ψ_k K_i ∇W_ik, and over the step K_i = p_i/ρ_i², the
// pressure both solves gave (dfsph_solve.hpp). So the object particle takes
//   F_k = Σ_i 2 m ρ0 ψ_k (p_i/ρ_i²) ∇W_ik,
// summed from its own side, without atomics (each boundary particle has its own twin in
// ObjectParticles), the same for any thread count. And the viscous force the force pass gave
// the fluid through it (fluid::ForceTerms::addObject), likewise negated. Adds to objects.force
// (xyz; w: fluid particles in reach).
//
// Under the position solver the fluid is moved, not accelerated, off the object particles:
// the solve gathers, iteration by iteration, m Σ Δx_ik of what its constraints moved the fluid
// by through each one (fluid::FluidParticles::objectPush), and the object particle takes
// F_k = -objectPush_k / Δt² over the substep (addConstraintReactions), with the viscous
// force as above and no pressure term.
#pragma once

#include <stdexcept>
#include <string>

#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbors.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"
#include "interaction/object_particles.hpp"
#include "sph/core/eos.hpp"
#include "sph/core/momentum.hpp"
#include "sph/core/read_only.hpp"

namespace sph::interaction {

namespace detail {

// Both forces in one walk over each boundary particle's fluid neighbours: under the position
// solver the viscous force alone, over the fluid its solve listed near each object particle
// (fluid::FluidParticles::objectNeighbors). A named template, not a generic lambda: nvcc's
// device lambdas may not sit inside one.
template <bool kArtificial, bool kPositionSolver, class B, class Kernels>
void addBoundaryForcesWith(const fluid::FluidParticles<B>& fluid, const fluid::Grid<B>& grid,
                           const fluid::BoundaryParticles<B>& boundary, ObjectParticles<B>& objects,
                           const fluid::FluidParameters& params, Kernels kernels) {
  const GridSpec spec = grid.spec;
  const std::uint32_t* cellStart = grid.cellStart.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const float* pressure = fluid.pressure.data();
  const float* density = fluid.density.data();
  const Vec4* state = fluid.pressureState.data();
  const Vec4* particle = boundary.position.data();  // w: ψ_k
  const Vec4* particleVelocity = boundary.velocity.data();
  const std::uint32_t* twin = boundary.id.data();  // its index in ObjectParticles
  const std::uint32_t* list = fluid.objectNeighbors.data();
  const std::uint32_t* listed = fluid.objectNeighborCount.data();
  const float reach = fluid::kObjectReach * params.h;
  Vec4* force = objects.force.data();
  const fluid::ForceConstants<float, Vec3, Kernels> constants(params, kernels);
  const float h2 = params.h * params.h;
  const float mass = params.mass, restDensity = params.restDensity;
  B::forEach(
      boundary.count, SPH_LAMBDA(std::size_t k) {
        const Vec4 xk = particle[k];
        const Vec3 vk = xyz(particleVelocity[k]);
        const float volumeMass = restDensity * xk.w;  // ρ0 ψ_k
        Vec3 sum{0.0f, 0.0f, 0.0f};                   // Σ_i of a_ik, the fluid's acceleration
        float near = 0.0f;
        // Named here, not first inside `if constexpr`: nvcc's device lambdas may not capture
        // there.
        (void)pressure;
        (void)density;
        (void)list;
        (void)listed;
        (void)reach;
        (void)spec;
        (void)cellStart;
        const auto visit = [&](std::uint32_t i) {
          const Vec3 rik = xyz(readOnly(position + i)) - xyz(xk);
          const float r2 = lengthSquared(rik);
          if (r2 >= h2 || r2 <= 0.0f) return;
          const auto pair = fluid::makePair(rik, r2, true, h2);
          const Vec3 gradW = pair.rij * pair.where(kernels.gradFactor(pair.r));
          if constexpr (!kPositionSolver) {
            const float ki =
                pressureOverDensitySquared(readOnly(pressure + i), readOnly(density + i));
            sum += pressureAccelerationSymmetric(volumeMass, ki, ki, gradW);
          }
          const float densityI = fluid::unpackPressureState(readOnly(state + i)).density;
          sum += fluid::boundaryFriction<kArtificial>(
              constants, densityI, volumeMass, xyz(readOnly(velocity + i)) - vk, pair, gradW);
          near += 1.0f;
        };
        if constexpr (kPositionSolver) {
          const std::uint32_t count = listed[k];
          if (count != fluid::kNeighborOverflow) {
            const std::uint32_t* mine = list + k * fluid::kObjectNeighborStride;
            for (std::uint32_t m = 0; m < count; ++m) visit(readOnly(mine + m));
          } else {
            fluid::forEachNeighborWithin(spec, cellStart, xyz(xk), reach, visit);
          }
        } else {
          fluid::forEachNeighbor(spec, cellStart, xyz(xk), visit);
        }
        const Vec4 f = force[twin[k]];
        force[twin[k]] = makeVec4(xyz(f) - sum * mass, f.w + near);
      });
}

}  // namespace detail

// `positionSolver`: the viscous force alone, over the position solver's lists; its push
// addConstraintReactions adds.
template <class B>
void addBoundaryForces(const fluid::FluidParticles<B>& fluid, const fluid::Grid<B>& grid,
                       const fluid::BoundaryParticles<B>& boundary, ObjectParticles<B>& objects,
                       const fluid::FluidParameters& params, bool positionSolver = false) {
  if (boundary.count == 0 || fluid.count == 0) return;
  // The position solver lists each object particle's fluid as it solves; a step that reached
  // here without those lists, or with another boundary's, is a bug in the stage order.
  if (positionSolver && fluid.objectNeighborCount.size() != boundary.count)
    throw std::logic_error("addBoundaryForces: the position solver listed the fluid near " +
                           std::to_string(fluid.objectNeighborCount.size()) +
                           " object particles, the boundary holds " +
                           std::to_string(boundary.count));
  const bool artificial = params.viscosityModel == ViscosityModel::Artificial;
  fluid::withKernels(params, [&](auto kernels) {
    if (artificial && !positionSolver)
      detail::addBoundaryForcesWith<true, false>(fluid, grid, boundary, objects, params, kernels);
    else if (artificial)
      detail::addBoundaryForcesWith<true, true>(fluid, grid, boundary, objects, params, kernels);
    else if (!positionSolver)
      detail::addBoundaryForcesWith<false, false>(fluid, grid, boundary, objects, params, kernels);
    else
      detail::addBoundaryForcesWith<false, true>(fluid, grid, boundary, objects, params, kernels);
  });
}

// Under the position solver, after its solve over the substep dt: -objectPush_k / dt² on each
// object particle (see above).
template <class B>
void addConstraintReactions(const fluid::FluidParticles<B>& fluid,
                            const fluid::BoundaryParticles<B>& boundary,
                            ObjectParticles<B>& objects, float dt) {
  if (boundary.count == 0 || fluid.objectPush.size() != boundary.count) return;
  const Vec4* push = fluid.objectPush.data();
  const std::uint32_t* twin = boundary.id.data();
  Vec4* force = objects.force.data();
  const float scale = 1.0f / (dt * dt);
  B::forEach(
      boundary.count, SPH_LAMBDA(std::size_t k) {
        const Vec4 f = force[twin[k]];
        force[twin[k]] = makeVec4(xyz(f) - xyz(push[k]) * scale, f.w);
      });
}

}  // namespace sph::interaction
