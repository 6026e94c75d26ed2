// probes.csv: one row per probe sample (Simulation::takeProbeRows), the time first, then one
// column per probe quantity with its unit in the name (README, "Outputs").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sph/io/row_file.hpp"
#include "sph/stats.hpp"

namespace sph::io {

class ProbesWriter {
 public:
  // Creates (truncates) the file and writes the header "time_s,<columns>". Throws
  // OutputError naming the path and the system error when it cannot be written.
  ProbesWriter(std::filesystem::path csvFile, const std::vector<std::string>& columns);
  // A resumed run's: the file cut back to the rows its checkpoint counted.
  ProbesWriter(std::filesystem::path csvFile, RowFile::Continue from);

  // Writes the rows, all of them or none (io/row_file.hpp). A NaN (a point probe in the air)
  // is written "nan".
  void append(const std::vector<ProbeRow>& rows);

 private:
  RowFile file_;
};

}  // namespace sph::io
