// Sampling an object's shape into particles (positions, outward normals, surface flags) and the
// interior test on the shape as built.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "objects/math3d.hpp"
#include "objects/mesh.hpp"
#include "objects/point_grid.hpp"
#include "sph/scene.hpp"

namespace sph::objects {

// A ring of consecutive samples around an axis: sample first + i at angle 2π (i + phase) / count
// in the shape's own frame. One sample is a ring's degenerate case, the centre of a disc.
struct SampleRing {
  std::size_t first = 0;
  int count = 0;
  double phase = 0.0;
};

struct ShapeSamples {
  std::vector<DVec3> position;  // m, world frame at the initial pose
  std::vector<DVec3> normal;    // outward unit normal of the nearest surface
  std::vector<std::uint8_t> surface;
  // A hollow tube's outer layer as rings in order along its surface (from one end's centre over
  // the disc, along the wall, over the other disc when capped): the surface drawn through them.
  std::vector<SampleRing> outerRings;
};

// What interiorContains needs of the initial shape.
struct BuiltShape {
  ShapeDesc desc;
  double spacing = 0.0;
  bool enclosesVolume = false;
  TriangleMesh mesh;       // meshes: scaled and placed
  PointGrid particleGrid;  // meshes: the sampled particles, for the margin test
  std::vector<DVec3> particles;

  // Whether p lies inside the cavity, at least `margin` inside the innermost particle layer.
  bool interiorContains(DVec3 p, double margin) const;
};

// Samples `shape` at `spacing` (> 0), its outer particles `inset` inside the described surface
// (box, sphere, capsule, surface mesh; a tube is described by its particle layer, and a solid
// mesh's lattice already lies inside). `where` prefixes error messages ("scene.json:
// objects[2]"); `sceneFolder` resolves relative mesh files. Throws InputError on impossible
// geometry; fills `built` for later interior tests.
ShapeSamples sampleShape(const ShapeDesc& shape, double spacing, double inset,
                         const std::string& where, const std::string& sceneFolder,
                         BuiltShape& built);

// `shape` with its surface moved `inset` inwards (box, sphere, capsule; others unchanged).
// Throws InputError naming the key when the shape is not thicker than that.
ShapeDesc insetShape(const ShapeDesc& shape, double inset, const std::string& where);

}  // namespace sph::objects
