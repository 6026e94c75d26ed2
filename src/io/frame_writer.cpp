#include "sph/io/frame_writer.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "io/csv_frame_writer.hpp"
#include "io/file_error.hpp"
#include "io/ply_writer.hpp"
#include "io/vtp_writer.hpp"

namespace sph::io {
namespace {

void requireLength(std::size_t actual, std::size_t expected, const char* name) {
  if (actual != expected) {
    throw std::invalid_argument(std::string("ParticleFrame::") + name + " holds " +
                                std::to_string(actual) + " values, expected " +
                                std::to_string(expected));
  }
}

}  // namespace

std::string formatDouble(double value) {
  char text[32];
  for (int precision = 15; precision <= 17; ++precision) {
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

void requireConsistentFrame(const ParticleFrame& frame) {
  const std::size_t n = frame.size();
  requireLength(frame.position.size(), 3 * n, "position");
  requireLength(frame.velocity.size(), 3 * n, "velocity");
  requireLength(frame.density.size(), n, "density");
  requireLength(frame.pressure.size(), n, "pressure");
  requireLength(frame.kind.size(), n, "kind");
  requireLength(frame.object.size(), n, "object");
}

void writeFileAtomically(const std::filesystem::path& file,
                         const std::function<void(std::ostream&)>& writeBody) {
  std::filesystem::path tmp = file;
  tmp += ".tmp";
  // Removes the temporary on every exit path except a successful rename.
  struct TmpGuard {
    const std::filesystem::path& path;
    bool keep = false;
    ~TmpGuard() {
      std::error_code ignored;
      if (!keep) std::filesystem::remove(path, ignored);
    }
  };

  errno = 0;
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throwFileError("open", tmp, errno);
  TmpGuard guard{tmp};

  errno = 0;
  writeBody(out);
  out.flush();
  if (!out) throwFileError("write", tmp, errno);
  errno = 0;
  out.close();
  if (!out) throwFileError("write", tmp, errno);

  // No fsync: the frame only has to survive the process being killed, not the machine losing
  // power, and an fsync per frame would dominate output time on slow disks.
  std::error_code renameError;
  std::filesystem::rename(tmp, file, renameError);
  // std::filesystem reports POSIX errno values in its error_code on the platforms we build for.
  if (renameError) throwFileError("rename onto", file, renameError.value());
  guard.keep = true;
}

void writeFrame(const ParticleFrame& frame, FrameFormat format, const std::filesystem::path& file) {
  if (format == FrameFormat::None) return;
  requireConsistentFrame(frame);
  writeFileAtomically(file, [&](std::ostream& out) {
    switch (format) {
      case FrameFormat::Vtp:
        writeVtp(frame, out);
        break;
      case FrameFormat::Ply:
        writePly(frame, out);
        break;
      case FrameFormat::Csv:
        writeCsvFrame(frame, out);
        break;
      case FrameFormat::None:
        break;
    }
  });
}

void writeParallelFrame(const std::vector<std::string>& pieces, bool torn,
                        const std::filesystem::path& file) {
  writeFileAtomically(file, [&](std::ostream& out) { writePvtp(pieces, torn, out); });
}

const char* frameExtension(FrameFormat format) {
  switch (format) {
    case FrameFormat::Vtp:
      return "vtp";
    case FrameFormat::Ply:
      return "ply";
    case FrameFormat::Csv:
      return "csv";
    case FrameFormat::None:
      return "";
  }
  return "";
}

}  // namespace sph::io
