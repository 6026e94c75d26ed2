// stats.csv: one row of FrameStats per output frame (the command-line contract in README.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sph/io/row_file.hpp"
#include "sph/stats.hpp"

namespace sph::io {

class StatsWriter {
 public:
  // Creates (truncates) the file and writes the header. Throws OutputError naming the path
  // and the system error when the file cannot be opened or written.
  // Each object named gets columns of its own: <name>_force_x .. _z (the fluid's contact force
  // on it, N) and <name>_com_x .. _z (its centre of mass, m).
  explicit StatsWriter(std::filesystem::path csvFile, std::vector<std::string> objectNames = {});
  // A resumed run's: the file cut back to the rows its checkpoint counted, `previous` the
  // statistics of the last of them.
  StatsWriter(std::filesystem::path csvFile, std::vector<std::string> objectNames,
              RowFile::Continue from, const FrameStats& previous);

  // Writes one row, whole or not at all (io/row_file.hpp), so every row appended is in the
  // file even if the process dies right after. The solver's iterations per step are those of
  // the steps since the last row.
  void append(const FrameStats& stats);

 private:
  std::size_t objectCount_;
  FrameStats previous_;  // the last row's counts
  RowFile file_;
};

}  // namespace sph::io
