// The scene's probes as the viewer shows them: each column's latest value and a window of its
// recent values to plot, fed with the rows the simulation samples (Simulation::takeProbeRows).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sph/stats.hpp"

namespace sph::view {

class ProbeReadings {
 public:
  // Keeps the last `kept` rows of each column.
  explicit ProbeReadings(std::size_t kept = 400) : kept_(kept) {}

  // Starts over with these columns (a new or reset simulation).
  void reset(const std::vector<std::string>& columns);
  void add(const std::vector<ProbeRow>& rows);

  const std::vector<std::string>& columns() const { return columns_; }
  // Column c's values, oldest first; NaN where a point probe was in the air.
  const std::vector<float>& history(std::size_t c) const { return history_[c]; }
  double latestTime() const { return latestTime_; }
  // Whether the panel plots column c: pressures, levels and forces; a point probe's density and
  // velocity are listed only.
  static bool plotted(const std::string& column);

 private:
  std::size_t kept_;
  std::vector<std::string> columns_;
  std::vector<std::vector<float>> history_;
  double latestTime_ = 0.0;
};

}  // namespace sph::view
