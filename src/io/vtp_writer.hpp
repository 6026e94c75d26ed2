// Serialises a ParticleFrame as binary VTK XML PolyData (.vtp) with the frame's fields as point
// data, which ParaView opens directly.
#pragma once

#include <ostream>

#include "sph/frame.hpp"

namespace sph::io {

// Writes the whole file to `out` (opened in binary mode); `frame` must be consistent
// (see requireConsistentFrame). Most callers want writeFrame, which also makes the file atomic.
void writeVtp(const ParticleFrame& frame, std::ostream& out);

}  // namespace sph::io
