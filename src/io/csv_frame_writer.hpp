// Serialises a ParticleFrame as CSV (.csv), one row per particle, for spreadsheets and quick
// scripts.
#pragma once

#include <ostream>

#include "sph/frame.hpp"

namespace sph::io {

// Writes the whole file to `out` (opened in binary mode); `frame` must be consistent
// (see requireConsistentFrame). Most callers want writeFrame, which also makes the file atomic.
void writeCsvFrame(const ParticleFrame& frame, std::ostream& out);

}  // namespace sph::io
