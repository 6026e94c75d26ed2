// Writing one particle frame to disk in the format the scene asks for. Files appear atomically:
// a reader (ParaView, `sph render`) or a killed run never sees a half-written frame.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "sph/frame.hpp"
#include "sph/scene.hpp"

namespace sph::io {

// Writes `frame` to `file` (extension not added). FrameFormat::None writes nothing.
// Throws OutputError naming the path and the system error when the file cannot be written,
// std::invalid_argument when the frame's arrays disagree in length.
void writeFrame(const ParticleFrame& frame, FrameFormat format, const std::filesystem::path& file);

// A distributed run's frame as one parallel file (.pvtp) over its pieces, each a process's VTP
// frame written by writeFrame, named relative to `file`'s folder (plain file names). ParaView
// opens it as one frame, readFrame as one frame in id order. `torn`: the pieces carry tears.
void writeParallelFrame(const std::vector<std::string>& pieces, bool torn,
                        const std::filesystem::path& file);

// "vtp", "ply", "csv"; "" for FrameFormat::None.
const char* frameExtension(FrameFormat format);

// Runs `writeBody` on a stream to `file` + ".tmp", then renames it over `file`. On any failure the
// temporary is removed and `file` is left as it was.
void writeFileAtomically(const std::filesystem::path& file,
                         const std::function<void(std::ostream&)>& writeBody);

// The shortest of %.15g, %.16g, %.17g that reads back as `value`: exact, yet 0.1 stays "0.1" for
// people reading the .pvd or the VTP's TIME.
std::string formatDouble(double value);

// Throws std::invalid_argument unless every array holds frame.size() entries (× 3 for vectors),
// so the writers can index them without bounds checks.
void requireConsistentFrame(const ParticleFrame& frame);

}  // namespace sph::io
