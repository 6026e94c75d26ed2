// A CSV file that grows by whole rows (stats.csv, probes.csv): each append reaches the file
// whole or not at all, so a disk that fills up mid-run leaves every earlier row readable and no
// row cut short.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace sph::io {

class RowFile {
 public:
  // Creates (truncates) the file and writes `header` (a line, its newline included). Throws
  // OutputError naming the path and the system error.
  RowFile(std::filesystem::path path, const std::string& header);
  // Opens the existing file to append to, cut back to its first `keepBytes` (the rows a
  // resumed run's checkpoint counted; later ones are written again). Throws OutputError naming
  // the path when it cannot be opened, and InputError when it is shorter than that.
  struct Continue {
    std::uintmax_t keepBytes;
  };
  RowFile(std::filesystem::path path, Continue from);
  ~RowFile();
  RowFile(const RowFile&) = delete;
  RowFile& operator=(const RowFile&) = delete;

  // Appends `rows` (whole lines), handed to the system at once: a process that dies right
  // after loses none of them. When the system takes only part (a full disk, a file size
  // limit), the file is cut back to the rows before and OutputError names the path and the
  // reason.
  void append(const std::string& rows);

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::size_t committed_ = 0;  // bytes of whole rows in the file
};

// Appends printf-formatted text to a row being built.
void appendFormatted(std::string& row, const char* format, ...)
    __attribute__((format(printf, 2, 3)));

}  // namespace sph::io
