// Reading back the frames this project writes (VTP, PLY, CSV; see frame_writer.hpp), for
// `sph render` and anything else that replays a finished run.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sph/frame.hpp"

namespace sph::io {

// Reads a frame file by its extension (.vtp, .ply or .csv; .pvtp, a distributed run's parallel
// frame, as its pieces joined in id order). Time and step come from the file where it holds
// them (VTP: time; PLY: time and step); CSV holds neither and reads as 0.
// Throws InputError naming the file and what was expected when it cannot be read.
ParticleFrame readFrame(const std::filesystem::path& file);

// The readers behind readFrame, on the whole file's bytes; `file` only names it in errors.
ParticleFrame readVtp(const std::string& bytes, const std::filesystem::path& file);
ParticleFrame readPly(const std::string& bytes, const std::filesystem::path& file);
ParticleFrame readCsvFrame(const std::string& text, const std::filesystem::path& file);

// The frame files of a run directory and its walls (DIR/boundary.EXT, written once; empty when
// the run has none). The frames are those DIR/frames.pvd lists, in its order, with their
// times, where the run wrote one (VTP); else DIR/frames/frame_NNNNN.EXT in frame order, times
// unknown.
struct RunFrameFiles {
  std::vector<std::filesystem::path> frames;
  std::vector<double> times;  // s, from frames.pvd; empty without it
  std::filesystem::path boundary;
  std::filesystem::path objectSurfaces;  // DIR/object_surfaces.vtp; empty when absent
};

// Throws InputError when `dir` holds no frames, or frames of more than one format, or a
// frames.pvd that cannot be read or lists a frame that is missing, naming the file.
RunFrameFiles listRunFrames(const std::filesystem::path& dir);

}  // namespace sph::io
