// probes.csv: one row per probe sample (Simulation::takeProbeRows), the time first, then one
// column per probe quantity with its unit in the name (README, "Outputs").
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sph/stats.hpp"

namespace sph::io {

class ProbesWriter {
 public:
  // Creates (truncates) the file and writes the header "time_s,<columns>". Throws
  // OutputError naming the path and the system error when it cannot be written.
  ProbesWriter(std::filesystem::path csvFile, const std::vector<std::string>& columns);

  // Writes the rows and flushes them. A NaN (a point probe in the air) is written "nan".
  void append(const std::vector<ProbeRow>& rows);

 private:
  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  std::filesystem::path path_;
  std::unique_ptr<std::FILE, FileCloser> file_;
};

}  // namespace sph::io
