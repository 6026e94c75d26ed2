// Serialises a ParticleFrame as binary little-endian PLY 1.0 (.ply), one vertex per particle, for
// point-cloud tools (MeshLab, Blender).
#pragma once

#include <ostream>

#include "sph/frame.hpp"

namespace sph::io {

// Writes the whole file to `out` (opened in binary mode); `frame` must be consistent
// (see requireConsistentFrame). Most callers want writeFrame, which also makes the file atomic.
void writePly(const ParticleFrame& frame, std::ostream& out);

}  // namespace sph::io
