// The surface an object is drawn with (sph/object_surface.hpp): triangles over its shape, each
// vertex tied to three of its surface particles. A hollow tube is drawn through its outer layer's
// particles themselves, ring to ring; other shapes by their described surface (a box's faces, a
// sphere's or capsule's latitudes, a mesh's own triangles), at about the particle spacing.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "objects/math3d.hpp"
#include "objects/shape_sampling.hpp"

namespace sph::objects {

struct DrawnSurface {
  std::vector<DVec3> vertex;                            // at the pose sampled, m
  std::vector<std::array<std::uint32_t, 3>> triangles;  // wound outward
  std::vector<std::array<std::uint32_t, 3>> anchor;     // per vertex, indices into the samples
  std::vector<DVec3> coordinate;                        // per vertex: α, β, h (anchoredPoint)
};

// `described` is the shape as the scene gives it (before a solid body's particles were moved in
// by half a spacing), `samples` its particles and `built` what sampling kept of it.
DrawnSurface drawnSurface(const ShapeDesc& described, const ShapeSamples& samples,
                          const BuiltShape& built, double spacing);

// α, β, h of `p` on the triangle (x0, x1, x2): the inverse of anchoredPoint.
DVec3 anchorCoordinates(DVec3 x0, DVec3 x1, DVec3 x2, DVec3 p);

}  // namespace sph::objects
