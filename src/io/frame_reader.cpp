#include "sph/io/frame_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>

#include "io/frame_reader_support.hpp"
#include "io/pvd_reader.hpp"
#include "io/pvtp_reader.hpp"

namespace sph::io {

namespace fs = std::filesystem;

std::string readFileBytes(const fs::path& file) {
  // A pipe would block the read forever, and a device (/dev/zero) never ends.
  std::error_code error;
  if (fs::exists(file, error) && !fs::is_regular_file(file, error))
    throw InputError(file.string() + ": is not a regular file (a directory, a device or a pipe)");
  constexpr std::uintmax_t kLargest = std::uintmax_t(4) << 30;  // 100 million particles
  const std::uintmax_t size = fs::file_size(file, error);
  if (!error && size > kLargest)
    throw InputError(file.string() + ": is " + std::to_string(size) +
                     " bytes; frames over 4 GiB are refused");
  errno = 0;
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw InputError(file.string() +
                     ": cannot open: " + (errno != 0 ? std::strerror(errno) : "unknown error"));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw InputError(file.string() + ": read error");
  return bytes.str();
}

namespace {

bool isFrameExtension(const std::string& ext) {
  return ext == ".vtp" || ext == ".ply" || ext == ".csv" || ext == ".pvtp";
}

// The walls a run wrote once beside frames of `extension`: a distributed run's parallel frames
// (.pvtp) have theirs in one piece (.vtp).
std::filesystem::path boundaryFile(const fs::path& dir, const std::string& extension) {
  return dir / (extension == ".pvtp" ? std::string("boundary.vtp") : "boundary" + extension);
}

// "frame_00012.vtp" → 12; -1 for any other name (temporaries, stray files, and numbers of more
// than 9 digits, which no run writes and which would not fit).
long frameNumber(const fs::path& file) {
  const std::string stem = file.stem().string();
  const std::string prefix = "frame_";
  if (stem.size() <= prefix.size() || stem.compare(0, prefix.size(), prefix) != 0) return -1;
  const std::string digits = stem.substr(prefix.size());
  if (digits.size() > 9 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return -1;
  return std::stol(digits);
}

}  // namespace

ParticleFrame readFrame(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (!isFrameExtension(ext))
    throwBadFrame(file, "unknown frame format '" + ext + "', expected .vtp, .pvtp, .ply or .csv");
  const std::string bytes = readFileBytes(file);
  if (ext == ".vtp") return readVtp(bytes, file);
  if (ext == ".pvtp") return joinPvtpPieces(readPvtpPieces(bytes, file), file);
  if (ext == ".ply") return readPly(bytes, file);
  return readCsvFrame(bytes, file);
}

namespace {

// The frames DIR/frames.pvd lists, in its order; each must be a frame file that exists.
RunFrameFiles framesOfSeries(const fs::path& dir, const fs::path& pvd) {
  constexpr std::uintmax_t kLargest = std::uintmax_t(256) << 20;  // 4 million frames
  std::error_code error;
  const std::uintmax_t size = fs::file_size(pvd, error);
  if (!error && size > kLargest)
    throw InputError(pvd.string() + ": is " + std::to_string(size) +
                     " bytes; a collection over 256 MiB is refused");
  RunFrameFiles files;
  std::string extension;
  for (const auto& [time, relative] : readPvd(readFileBytes(pvd), pvd)) {
    const fs::path frame = dir / relative;
    const std::string ext = frame.extension().string();
    if (!isFrameExtension(ext))
      throw InputError(pvd.string() + ": lists '" + relative +
                       "', not a .vtp, .pvtp, .ply or .csv frame");
    if (extension.empty()) extension = ext;
    if (ext != extension)
      throw InputError(pvd.string() + ": lists frames of two formats (" + extension + " and " +
                       ext + "); expected one");
    if (!fs::is_regular_file(frame, error))
      throw InputError(pvd.string() + ": lists '" + relative + "', which is missing");
    files.frames.push_back(frame);
    files.times.push_back(time);
  }
  const fs::path boundary = boundaryFile(dir, extension);
  if (fs::is_regular_file(boundary, error)) files.boundary = boundary;
  if (fs::is_regular_file(dir / "object_surfaces.vtp", error))
    files.objectSurfaces = dir / "object_surfaces.vtp";
  return files;
}

}  // namespace

RunFrameFiles listRunFrames(const fs::path& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) throw InputError(dir.string() + ": not a directory");
  const fs::path pvd = dir / "frames.pvd";
  if (fs::exists(pvd, error)) return framesOfSeries(dir, pvd);
  const fs::path framesDir = dir / "frames";
  if (!fs::is_directory(framesDir, error))
    throw InputError(framesDir.string() +
                     ": not found; expected the frames of a run (sph run --out DIR)");

  std::vector<std::pair<long, fs::path>> numbered;
  std::string extension;
  for (const fs::directory_entry& entry : fs::directory_iterator(framesDir, error)) {
    const fs::path& path = entry.path();
    const long number = frameNumber(path);
    if (number < 0 || !isFrameExtension(path.extension().string())) continue;
    if (extension.empty()) extension = path.extension().string();
    if (path.extension() != extension)
      throw InputError(framesDir.string() + ": holds frames of two formats (" + extension +
                       " and " + path.extension().string() + "); expected one");
    numbered.emplace_back(number, path);
  }
  if (error) throw InputError(framesDir.string() + ": cannot list: " + error.message());
  if (numbered.empty())
    throw InputError(framesDir.string() +
                     ": holds no frame_NNNNN.vtp, .ply or .csv files (was the run's format "
                     "'none'?)");
  std::sort(numbered.begin(), numbered.end());

  RunFrameFiles files;
  for (auto& [number, path] : numbered) files.frames.push_back(std::move(path));
  const fs::path boundary = boundaryFile(dir, extension);
  if (fs::is_regular_file(boundary, error)) files.boundary = boundary;
  if (fs::is_regular_file(dir / "object_surfaces.vtp", error))
    files.objectSurfaces = dir / "object_surfaces.vtp";
  return files;
}

}  // namespace sph::io
