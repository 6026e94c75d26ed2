// A fluid's particles as a closed surface mesh, through OpenVDB: each particle rasterised as a
// sphere into a narrow-band level set (the union of the spheres), smoothed, moved in to where
// the fluid ends, and meshed at its zero crossing.
#pragma once

#include <vector>

#include "triangle_mesh.hpp"

namespace sph::surface {

struct SurfaceSettings {
  double spacing = 0.0;  // the fluid's particle spacing, m
  // The level set's voxel edge in spacings: finer costs the cube of it.
  double voxel = 0.6;
  // Mean-curvature smoothing passes of the level set: each flattens the spheres' bumps a
  // little more and rounds the liquid's edges a little more.
  int smoothing = 3;
};

// Spheres of one spacing's radius overlap their neighbours into one solid; the surface is
// then moved in to where the fluid ends, half a spacing past its outer particles, so that it
// encloses the fluid's volume (a resting drop's within 1 %, a tank's within 2 %). `points`: x, y, z
// per particle. Throws std::invalid_argument for a spacing or voxel that is not positive.
TriangleMesh reconstructSurface(const std::vector<float>& points, const SurfaceSettings& settings);

}  // namespace sph::surface
