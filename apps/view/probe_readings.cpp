#include "probe_readings.hpp"

namespace sph::view {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

void ProbeReadings::reset(const std::vector<std::string>& columns) {
  columns_ = columns;
  history_.assign(columns.size(), {});
  latestTime_ = 0.0;
}

void ProbeReadings::add(const std::vector<ProbeRow>& rows) {
  for (const ProbeRow& row : rows) {
    for (std::size_t c = 0; c < history_.size() && c < row.values.size(); ++c) {
      std::vector<float>& h = history_[c];
      h.push_back(float(row.values[c]));
      if (h.size() > kept_) h.erase(h.begin(), h.begin() + std::ptrdiff_t(h.size() - kept_));
    }
    latestTime_ = row.time;
  }
}

bool ProbeReadings::plotted(const std::string& column) {
  for (const char* suffix : {"_pressure_Pa", "_level_m", "_fx_N", "_fy_N", "_fz_N"})
    if (endsWith(column, suffix)) return true;
  return false;
}

}  // namespace sph::view
