// The files of one run (README.md, Outputs): DIR/frames/frame_NNNNN.EXT, DIR/frames.pvd,
// DIR/stats.csv, DIR/summary.json and the walls in DIR/boundary.EXT. An earlier run is never
// overwritten unless asked.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "checkpoint.hpp"
#include "sph/frame.hpp"
#include "sph/io/probes_writer.hpp"
#include "sph/io/pvd_series.hpp"
#include "sph/io/stats_writer.hpp"
#include "sph/object_surface.hpp"
#include "sph/scene.hpp"
#include "sph/simulation.hpp"
#include "sph/stats.hpp"

namespace sph::cli {

// A process's share of a run across several (mpirun): each writes its particles of every frame
// as a piece, DIR/frames/frame_NNNNN_R.vtp; process 0 writes the rest, the frame over the
// pieces (frame_NNNNN.pvtp, one frame in ParaView), the series and the statistics.
struct RunPiece {
  int rank = 0;
  int ranks = 1;
};

class RunOutput {
 public:
  // Throws InputError if `dir` holds an earlier run and `force` is false.
  // `objectNames` give stats.csv columns of their own. A piece other than process 0's finds
  // the directory as process 0 made it, and only writes its pieces; the run's frames are
  // VTP.
  RunOutput(std::filesystem::path dir, FrameFormat format, bool force,
            std::vector<std::string> objectNames = {}, RunPiece piece = {});

  // A resumed run's: `dir` as the checkpoint at `position` left it. Frames after its frame, and
  // rows after those it counted, are removed (a run killed after the checkpoint wrote them;
  // they are written again); `previous` are the statistics of its last row.
  RunOutput(std::filesystem::path dir, FrameFormat format, std::vector<std::string> objectNames,
            const RunPosition& position, const FrameStats& previous);

  ~RunOutput();  // waits for the frames queued

  // Frames hold the fluid; the static walls go once into DIR/boundary.EXT.
  void writeBoundary(const ParticleFrame& walls);
  // The objects' drawn surfaces go once into DIR/object_surfaces.vtp, for sph render.
  void writeObjectSurfaces(const std::vector<ObjectSurfaceMesh>& surfaces);
  // Queues the frame; a thread of its own assembles and writes the frames in order while the
  // simulation goes on. Throws the error of an earlier frame's writing, if any.
  void writeFrame(FrameCapture capture, double wallMsPerStep);
  // Waits until every queued frame is written; throws the first writing error.
  void finish();
  // The probes' rows into DIR/probes.csv, made with its header on the first call (none
  // without probes).
  void writeProbes(const std::vector<std::string>& columns, const std::vector<ProbeRow>& rows);
  const std::filesystem::path& dir() const { return dir_; }
  // Where the outputs stand once every frame queued is written (a checkpoint's RunPosition).
  // Throws the first writing error.
  RunPosition position();
  int framesWritten() const;

 private:
  struct Queued {
    FrameCapture capture;
    double wallMsPerStep;
  };
  void writeQueued();
  void write(const ParticleFrame& frame, const FrameStats& stats);
  void writePiece(const ParticleFrame& frame, const FrameStats& stats);

  std::filesystem::path dir_;
  FrameFormat format_;
  RunPiece piece_;
  std::optional<io::PvdSeries> series_;
  std::optional<io::StatsWriter> stats_;
  std::optional<io::ProbesWriter> probes_;
  int frames_ = 0;

  // The writer thread and what it shares with the simulation's.
  static constexpr std::size_t kMaxQueued = 2;  // bounds the memory of frames in flight
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Queued> queue_;
  bool writing_ = false;  // the writer holds a frame taken from the queue
  bool stopping_ = false;
  std::exception_ptr error_;
  std::thread writer_;
};

}  // namespace sph::cli
