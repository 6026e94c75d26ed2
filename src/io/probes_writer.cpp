#include "sph/io/probes_writer.hpp"

#include <cmath>
#include <string>
#include <utility>

namespace sph::io {

namespace {

std::string headerOf(const std::vector<std::string>& columns) {
  std::string header = "time_s";
  for (const std::string& column : columns) header += "," + column;
  return header + "\n";
}

}  // namespace

ProbesWriter::ProbesWriter(std::filesystem::path csvFile, const std::vector<std::string>& columns)
    : file_(std::move(csvFile), headerOf(columns)) {}

ProbesWriter::ProbesWriter(std::filesystem::path csvFile, RowFile::Continue from)
    : file_(std::move(csvFile), from) {}

void ProbesWriter::append(const std::vector<ProbeRow>& rows) {
  if (rows.empty()) return;
  std::string text;
  for (const ProbeRow& row : rows) {
    appendFormatted(text, "%.9g", row.time);
    for (double v : row.values) {
      if (std::isnan(v)) {
        text += ",nan";
      } else {
        appendFormatted(text, ",%.9g", v);
      }
    }
    text += '\n';
  }
  file_.append(text);
}

}  // namespace sph::io
