// The files of one run (DESIGN.md): DIR/frames/frame_NNNNN.EXT, DIR/frames.pvd, DIR/stats.csv,
// DIR/summary.json and the walls in DIR/boundary.EXT. An earlier run is never overwritten unless
// asked.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/pvd_series.hpp"
#include "io/stats_writer.hpp"
#include "sph/frame.hpp"
#include "sph/scene.hpp"
#include "sph/stats.hpp"

namespace sph::cli {

class RunOutput {
 public:
  // Throws InputError if `dir` holds an earlier run and `force` is false.
  // `objectNames` give stats.csv columns of their own.
  RunOutput(std::filesystem::path dir, FrameFormat format, bool force,
            std::vector<std::string> objectNames = {});

  // Frames hold the fluid; the static walls go once into DIR/boundary.EXT.
  void writeBoundary(const ParticleFrame& walls);
  void writeFrame(const ParticleFrame& frame, const FrameStats& stats);
  const std::filesystem::path& dir() const { return dir_; }
  int framesWritten() const { return frames_; }

 private:
  std::filesystem::path dir_;
  FrameFormat format_;
  std::optional<io::PvdSeries> series_;
  std::optional<io::StatsWriter> stats_;
  int frames_ = 0;
};

}  // namespace sph::cli
