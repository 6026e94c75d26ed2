// stats.csv: one row of FrameStats per output frame (the command-line contract in README.md).
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sph/stats.hpp"

namespace sph::io {

class StatsWriter {
 public:
  // Creates (truncates) the file and writes the header. Throws OutputError naming the path
  // and the system error when the file cannot be opened or written.
  // Each object named gets columns of its own: <name>_force_x .. _z (the fluid's contact force
  // on it, N) and <name>_com_x .. _z (its centre of mass, m).
  explicit StatsWriter(std::filesystem::path csvFile, std::vector<std::string> objectNames = {});

  // Writes one row and flushes it, so every row appended is on disk even if the process dies
  // right after. The solver's iterations per step are those of the steps since the last row.
  void append(const FrameStats& stats);

 private:
  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };

  void flushOrThrow();

  std::filesystem::path path_;
  std::size_t objectCount_;
  FrameStats previous_;  // the last row's counts
  std::unique_ptr<std::FILE, FileCloser> file_;
};

}  // namespace sph::io
