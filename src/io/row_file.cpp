#include "sph/io/row_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <utility>

#include "sph/error.hpp"

#include "io/file_error.hpp"

namespace sph::io {

RowFile::RowFile(std::filesystem::path path, const std::string& header) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throwFileError("open", path_, errno);
  append(header);
}

RowFile::RowFile(std::filesystem::path path, Continue from) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd_ < 0) throwFileError("open", path_, errno);
  const off_t end = ::lseek(fd_, 0, SEEK_END);
  if (end < 0) throwFileError("seek in", path_, errno);
  if (std::uintmax_t(end) < from.keepBytes)
    throw InputError(path_.string() + ": holds " + std::to_string(end) + " bytes, fewer than the " +
                     std::to_string(from.keepBytes) +
                     " the checkpoint counted: it was changed since");
  if (::ftruncate(fd_, off_t(from.keepBytes)) != 0) throwFileError("truncate", path_, errno);
  if (::lseek(fd_, off_t(from.keepBytes), SEEK_SET) < 0) throwFileError("seek in", path_, errno);
  committed_ = std::size_t(from.keepBytes);
}

RowFile::~RowFile() {
  if (fd_ >= 0) ::close(fd_);
}

void RowFile::append(const std::string& rows) {
  std::size_t written = 0;
  while (written < rows.size()) {
    const ssize_t n = ::write(fd_, rows.data() + written, rows.size() - written);
    if (n > 0) {
      written += std::size_t(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    const int error = n < 0 ? errno : ENOSPC;
    // What reached the file of these rows goes: the rows before stay whole.
    if (::ftruncate(fd_, off_t(committed_)) == 0) ::lseek(fd_, off_t(committed_), SEEK_SET);
    throwFileError("write", path_, error);
  }
  committed_ += rows.size();
}

void appendFormatted(std::string& row, const char* format, ...) {
  char buffer[512];
  va_list arguments;
  va_start(arguments, format);
  const int n = std::vsnprintf(buffer, sizeof buffer, format, arguments);
  va_end(arguments);
  if (n > 0)
    row.append(buffer, std::size_t(n) < sizeof buffer ? std::size_t(n) : sizeof buffer - 1);
}

}  // namespace sph::io
