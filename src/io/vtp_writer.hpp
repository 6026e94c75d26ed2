// Serialises a ParticleFrame as binary VTK XML PolyData (.vtp) with the frame's fields as point
// data, which ParaView opens directly.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "sph/frame.hpp"

namespace sph::io {

// Writes the whole file to `out` (opened in binary mode); `frame` must be consistent
// (see requireConsistentFrame). Most callers want writeFrame, which also makes the file atomic.
void writeVtp(const ParticleFrame& frame, std::ostream& out);

// A frame's point arrays as the VTP writer writes them, in order (`torn`: with the tears).
struct PointArrayTag {
  const char* type;
  const char* name;
  int components;
  std::size_t bytes;  // of one component
};
std::vector<PointArrayTag> framePointArrays(bool torn);

// A parallel frame (.pvtp): the arrays of its pieces, and the pieces' files, relative to the
// .pvtp's folder (plain names: no XML escapes needed), one a process of a distributed run.
// ParaView opens it as one frame.
void writePvtp(const std::vector<std::string>& pieces, bool torn, std::ostream& out);

}  // namespace sph::io
