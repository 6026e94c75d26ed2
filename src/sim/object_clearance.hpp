// Where fluid may start among the objects: a fluid particle that starts inside a solid, or
// within the reach of an object particle's influence sphere, would be thrown out by the first
// contact forces or ride along inside a hollow body as trapped weight.
#pragma once

#include <functional>
#include <vector>

#include "objects/object_world.hpp"
#include "sph/core/vec.hpp"

namespace sph::sim {

// Removes from `points` every point within `reachOf(radius)` of an object particle of that
// radius, and every point in the cavity of a closed object other than `container` (the object
// a block is declared `inside`, or -1). Across a periodic face of the world's, an object blocks
// through its images. Keeps the order of the points that remain.
void removeObjectOverlap(std::vector<Vec3>& points, const objects::ObjectWorld& world,
                         const std::function<float(float)>& reachOf, int container);

}  // namespace sph::sim
