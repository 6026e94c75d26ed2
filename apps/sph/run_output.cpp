#include "run_output.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "sph/error.hpp"
#include "sph/io/frame_writer.hpp"
#include "sph/io/object_surface_file.hpp"
#include "sph/threads.hpp"

namespace sph::cli {

namespace fs = std::filesystem;

namespace {

// The files a run writes; --force removes these, the temporaries of a run killed while writing
// them, and nothing else.
const char* const kRunFiles[] = {"frames",       "frames.pvd",   "stats.csv",
                                 "probes.csv",   "summary.json", "boundary.vtp",
                                 "boundary.ply", "boundary.csv", "object_surfaces.vtp",
                                 "images",       "video.mp4",    "checkpoints"};

// A file and what a run killed while writing it left: "<name>.tmp" (io/frame_writer.hpp).
std::vector<fs::path> runFiles(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const char* name : kRunFiles) {
    files.push_back(dir / name);
    files.push_back(dir / (std::string(name) + ".tmp"));
  }
  return files;
}

bool holdsEarlierRun(const fs::path& dir) {
  for (const fs::path& file : runFiles(dir))
    if (fs::exists(file)) return true;
  return false;
}

}  // namespace

RunOutput::RunOutput(fs::path dir, FrameFormat format, bool force,
                     std::vector<std::string> objectNames, RunPiece piece)
    : dir_(std::move(dir)), format_(format), piece_(piece) {
  if (piece_.ranks > 1 && format_ != FrameFormat::Vtp && format_ != FrameFormat::None)
    throw InputError(std::string("output.format: \"") + io::frameExtension(format_) +
                     "\": a run across processes writes its frames in pieces, as vtp; expected "
                     "\"vtp\" or \"none\"");
  if (piece_.rank != 0) return;  // process 0 has made the directory
  if (holdsEarlierRun(dir_)) {
    if (!force)
      throw InputError(dir_.string() +
                       ": holds an earlier run; pass --force to overwrite it or choose another "
                       "--out directory");
    for (const fs::path& file : runFiles(dir_)) {
      std::error_code error;
      fs::remove_all(file, error);
      if (error)
        throw OutputError("cannot remove the earlier run's '" + file.string() +
                          "': " + error.message());
    }
  }
  std::error_code error;
  fs::create_directories(dir_ / "frames", error);
  if (error)
    throw OutputError("cannot create the output directory '" + (dir_ / "frames").string() +
                      "': " + error.message());
  stats_.emplace(dir_ / "stats.csv", std::move(objectNames));
  if (format_ == FrameFormat::Vtp) series_.emplace(dir_ / "frames.pvd");
}

RunOutput::RunOutput(fs::path dir, FrameFormat format, std::vector<std::string> objectNames,
                     const RunPosition& position, const FrameStats& previous)
    : dir_(std::move(dir)), format_(format), frames_(position.frame + 1) {
  // Frames past the checkpoint's, and what a kill left half written.
  std::error_code error;
  for (fs::directory_iterator it(dir_ / "frames", error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    long index = -1;  // strtol, not atoi: a stray name of many digits saturates
    if (name.rfind("frame_", 0) == 0 && name.size() > 11)
      index = std::strtol(name.c_str() + 6, nullptr, 10);
    const bool temporary = it->path().extension() == ".tmp";
    if (temporary || index > position.frame) {
      std::error_code removeError;
      fs::remove(it->path(), removeError);
      if (removeError)
        throw OutputError("cannot remove '" + it->path().string() + "': " + removeError.message());
    }
  }
  stats_.emplace(dir_ / "stats.csv", std::move(objectNames),
                 io::RowFile::Continue{position.statsBytes}, previous);
  if (position.probesBytes > 0)
    probes_.emplace(dir_ / "probes.csv", io::RowFile::Continue{position.probesBytes});
  if (format_ == FrameFormat::Vtp) series_.emplace(dir_ / "frames.pvd", position.series);
}

RunPosition RunOutput::position() {
  finish();
  RunPosition p;
  p.frame = framesWritten() - 1;
  const auto sizeOf = [](const fs::path& file) {
    std::error_code error;
    const std::uintmax_t size = fs::file_size(file, error);
    if (error)
      throw OutputError("cannot read the size of '" + file.string() + "': " + error.message());
    return size;
  };
  p.statsBytes = sizeOf(dir_ / "stats.csv");
  p.probesBytes = probes_ ? sizeOf(dir_ / "probes.csv") : 0;
  if (series_) p.series = series_->frames();
  return p;
}

void RunOutput::writeBoundary(const ParticleFrame& walls) {
  if (format_ == FrameFormat::None || walls.size() == 0) return;
  io::writeFrame(walls, format_, dir_ / (std::string("boundary.") + io::frameExtension(format_)));
}

void RunOutput::writeObjectSurfaces(const std::vector<ObjectSurfaceMesh>& surfaces) {
  if (format_ == FrameFormat::None || surfaces.empty()) return;
  io::writeObjectSurfaces(surfaces, dir_ / "object_surfaces.vtp");
}

RunOutput::~RunOutput() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (writer_.joinable()) writer_.join();
}

void RunOutput::writeFrame(FrameCapture capture, double wallMsPerStep) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!writer_.joinable()) writer_ = std::thread([this] { writeQueued(); });
  changed_.wait(lock, [&] { return queue_.size() < kMaxQueued || error_; });
  if (error_) std::rethrow_exception(error_);
  queue_.push_back({std::move(capture), wallMsPerStep});
  changed_.notify_all();
}

void RunOutput::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return (queue_.empty() && !writing_) || error_; });
  if (error_) std::rethrow_exception(error_);
}

void RunOutput::writeProbes(const std::vector<std::string>& columns,
                            const std::vector<ProbeRow>& rows) {
  if (columns.empty()) return;
  if (!probes_) probes_.emplace(dir_ / "probes.csv", columns);
  probes_->append(rows);
}

int RunOutput::framesWritten() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return frames_;
}

void RunOutput::writeQueued() {
  runSeriallyOnThisThread();  // the frame's sums, beside the stepping threads
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return !queue_.empty() || stopping_; });
    if (queue_.empty()) return;  // stopping, and all written
    Queued next = std::move(queue_.front());
    queue_.pop_front();
    writing_ = true;
    lock.unlock();
    try {
      if (!error_) {
        ParticleFrame frame;
        FrameStats stats;
        next.capture.take(frame, stats);
        stats.wallMsPerStep = next.wallMsPerStep;
        write(frame, stats);
      }
    } catch (...) {
      lock.lock();
      if (!error_) error_ = std::current_exception();
      lock.unlock();
    }
    lock.lock();
    writing_ = false;
    changed_.notify_all();
  }
}

void RunOutput::write(const ParticleFrame& frame, const FrameStats& stats) {
  if (piece_.ranks > 1) {
    writePiece(frame, stats);
    return;
  }
  if (format_ != FrameFormat::None) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%05d.%s", frames_, io::frameExtension(format_));
    io::writeFrame(frame, format_, dir_ / "frames" / name);
    if (series_) series_->add(frame.time, std::string("frames/") + name);
  }
  stats_->append(stats);
  std::lock_guard<std::mutex> lock(mutex_);
  ++frames_;
}

void RunOutput::writePiece(const ParticleFrame& frame, const FrameStats& stats) {
  if (format_ == FrameFormat::Vtp) {
    // A rank's piece, or (rank -1) the frame over them.
    const auto named = [&](int rank) {
      char name[64];
      if (rank < 0)
        std::snprintf(name, sizeof name, "frame_%05d.pvtp", frames_);
      else
        std::snprintf(name, sizeof name, "frame_%05d_%d.vtp", frames_, rank);
      return std::string(name);
    };
    io::writeFrame(frame, format_, dir_ / "frames" / named(piece_.rank));
    if (piece_.rank == 0) {
      std::vector<std::string> pieces;
      for (int r = 0; r < piece_.ranks; ++r) pieces.push_back(named(r));
      const std::string whole = named(-1);
      io::writeParallelFrame(pieces, /*torn=*/false, dir_ / "frames" / whole);
      series_->add(frame.time, "frames/" + whole);
    }
  }
  if (piece_.rank == 0) stats_->append(stats);
  std::lock_guard<std::mutex> lock(mutex_);
  ++frames_;
}

}  // namespace sph::cli
