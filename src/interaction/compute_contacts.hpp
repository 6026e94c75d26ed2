// Stage: collision detection and contact forces between fluid and object particles (Meteer 2011,
// §7.3-7.4, Algorithm 3, §8.2-8.3), equal and opposite:
//   fluid pass   each fluid particle sums the forces from the object particles it touches,
//                adds them to its acceleration and clamps the total (§8.3); it also updates
//                whether it is still inside the object that held it at the start;
//   object pass  each object particle sums the reactions from the fluid particles it touches.
// Both passes evaluate every pair with the same arguments, so each pair's two forces are exact
// negations and no atomics are needed: the result is the same for any thread count. With
// boundary coupling (params.boundary) neither adds a force: the fluid pass only tracks
// containment, and the pressure solve's reactions come from boundary_forces.hpp.
// Reads the fluid's position, velocity, id, grid and acceleration and the object particles.
// Writes the fluid's acceleration, the containment state and objects.force.
#pragma once

#include "fluid/neighbors.hpp"
#include "fluid/particles.hpp"
#include "interaction/object_particles.hpp"
#include "interaction/prepare_object_particles.hpp"
#include "sph/core/contact.hpp"
#include "sph/core/read_only.hpp"

namespace sph::interaction {

namespace detail {

// The force on fluid particle (xf, vf) from object particle (xo, vo, radius, cut): Meteer 2011,
// eqs. 13-16 through the influence sphere, the spring scaled by the distance function.
SPH_HD Vec3 fluidContactForce(const InteractionParameters& p, Vec3 xf, Vec3 vf, Vec4 xo, Vec4 vo) {
  const float reach = contactReach(p, radiusOf(xo));
  const Vec3 offset = xf - xyz(xo);
  const float r2 = lengthSquared(offset);
  if (r2 >= reach * reach) return Vec3{0.0f, 0.0f, 0.0f};
  const float scale = p.distance(realSqrt(r2) / reach);
  const bool damped = !(p.cutAwareDamping && isCut(vo));
  return demContactForce(p.contact, offset, xyz(vo) - vf, reach, scale, damped);
}

SPH_HD bool insideBox(const Vec4* bounds, std::int32_t object, Vec3 p) {
  const Vec4 lo = bounds[2 * object], hi = bounds[2 * object + 1];
  return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
}

SPH_HD Vec3 clampLength(Vec3 v, float maxLength) {
  const float l2 = lengthSquared(v);
  if (maxLength <= 0.0f || l2 <= maxLength * maxLength) return v;
  return v * (maxLength / realSqrt(l2));
}

}  // namespace detail

// Returns the number of fluid–object pairs in contact.
template <class B>
std::size_t computeContacts(fluid::FluidParticles<B>& fluid, const fluid::Grid<B>& fluidGrid,
                            ObjectParticles<B>& objects, ContainmentState<B>& containment,
                            const InteractionParameters& params) {
  if (objects.count == 0 || fluid.count == 0) return 0;
  const InteractionParameters p = params;
  const GridSpec objectGrid = objects.grid;
  const std::uint32_t* objectCellStart = objects.cellStart.data();
  const Vec4* objectPosition = objects.position.data();
  const Vec4* objectVelocity = objects.velocity.data();
  const Vec4* objectNormal = objects.normal.data();
  Vec4* objectForce = objects.force.data();
  const Vec4* objectBounds = objects.bounds.data();
  const GridSpec spec = fluidGrid.spec;
  const std::uint32_t* fluidCellStart = fluidGrid.cellStart.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const std::uint32_t* id = fluid.id.data();
  Vec4* acceleration = fluid.acceleration.data();
  const std::int32_t* containerById =
      containment.containerById.size() ? containment.containerById.data() : nullptr;
  std::uint32_t* insideById = containment.insideById.data();
  Vec4* firstExitById = containment.firstExitById.data();
  const float inverseMass = 1.0f / p.fluidMass;

  B::forEach(
      fluid.count, SPH_LAMBDA(std::size_t i) {
        const Vec3 xi = xyz(position[i]);
        const Vec4 ai = acceleration[i];
        Vec3 force{0.0f, 0.0f, 0.0f};
        const std::int32_t container = containerById ? containerById[id[i]] : -1;
        // Which side of its container's wall the particle is on: the mean signed distance
        // along the outward normals of the container's intact particles in reach, weighted
        // toward the nearest.
        const float reach2 = objectGrid.cellSize * objectGrid.cellSize;
        float sideSum = 0.0f, weightSum = 0.0f;
        int sideCount = 0;
        // With boundary coupling the walk is only for containment: none for a free particle.
        if ((!p.boundary || container >= 0) && fluid::nearGrid(objectGrid, xi)) {
          const Vec3 vi = xyz(velocity[i]);
          fluid::forEachNeighborWithin(
              objectGrid, objectCellStart, xi, objectGrid.cellSize, [&](std::uint32_t o) {
                const Vec4 xo = readOnly(objectPosition + o);
                const Vec4 vo = readOnly(objectVelocity + o);
                if (!p.boundary) force += detail::fluidContactForce(p, xi, vi, xo, vo);
                const Vec4 no = readOnly(objectNormal + o);
                // Torn particles (w of the velocity) have no surface to be on a side of.
                if (container >= 0 && objectOf(no) == container && !isCut(vo)) {
                  const Vec3 offset = xi - xyz(xo);
                  const float r2 = lengthSquared(offset);
                  if (r2 < reach2) {
                    const float w = (reach2 - r2) * (reach2 - r2);
                    sideSum += w * dot(offset, xyz(no));
                    weightSum += w;
                    ++sideCount;
                  }
                }
              });
        }
        const Vec3 a = detail::clampLength(xyz(ai) + force * inverseMass, p.maxAcceleration);
        acceleration[i] = makeVec4(a, ai.w);
        // A particle squeezing through a wall passes within reach of several of its particles
        // and gets past their layer by more than half its radius: "outside" asks for both,
        // which a particle pressed against the tip of a crease in a crumpled wall (one or two
        // wall particles in reach, their normals poorly defined) does not meet. Past the box
        // around the container's intact particles it is out however it got there (through a
        // tear, whose torn particles say nothing of sides). Elsewhere the last answer stands:
        // nothing crosses a wall without passing near it.
        const bool beyond = container >= 0 && !detail::insideBox(objectBounds, container, xi);
        if (weightSum > 0.0f || beyond) {
          const float side = weightSum > 0.0f ? sideSum / weightSum : 0.0f;
          const std::uint32_t k = id[i];
          const bool past = beyond || (side > 0.5f * p.fluidRadius && sideCount >= 3);
          const std::uint32_t inside = past ? 0u : (side < 0.0f ? 1u : insideById[k]);
          if (insideById[k] == 1u && inside == 0u && firstExitById[k].w == 0.0f)
            firstExitById[k] = makeVec4(xi, 1.0f);
          insideById[k] = inside;
        }
      });

  B::forEach(
      objects.count, SPH_LAMBDA(std::size_t o) {
        const Vec4 xo = objectPosition[o];
        const Vec4 vo = objectVelocity[o];
        Vec3 force{0.0f, 0.0f, 0.0f};
        float touching = 0.0f;
        if (!p.boundary && fluid::nearGrid(spec, xyz(xo))) {
          const float reach = contactReach(p, radiusOf(xo));
          fluid::forEachNeighborWithin(spec, fluidCellStart, xyz(xo), reach, [&](std::uint32_t j) {
            const Vec3 xj = xyz(readOnly(position + j));
            if (lengthSquared(xj - xyz(xo)) >= reach * reach) return;
            force -= detail::fluidContactForce(p, xj, xyz(readOnly(velocity + j)), xo, vo);
            touching += 1.0f;
          });
        }
        objectForce[o] = makeVec4(force, touching);
      });
  return B::reduce(
      objects.count, std::size_t{0},
      SPH_LAMBDA(std::size_t o) { return std::size_t(objectForce[o].w); },
      SPH_LAMBDA(std::size_t a, std::size_t b) { return a + b; });
}

}  // namespace sph::interaction
