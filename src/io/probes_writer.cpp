#include "io/probes_writer.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace sph::io {

namespace {

std::string headerOf(const std::vector<std::string>& columns) {
  std::string header = "time_s";
  for (const std::string& column : columns) header += "," + column;
  return header + "\n";
}

void appendNumber(std::string& out, double v) {
  char buffer[32];
  const int n = std::snprintf(buffer, sizeof buffer, "%.9g", v);
  if (n > 0)
    out.append(buffer, std::size_t(n) < sizeof buffer ? std::size_t(n) : sizeof buffer - 1);
}

}  // namespace

ProbesWriter::ProbesWriter(std::filesystem::path csvFile, const std::vector<std::string>& columns)
    : file_(std::move(csvFile), headerOf(columns)) {}

void ProbesWriter::append(const std::vector<ProbeRow>& rows) {
  if (rows.empty()) return;
  std::string text;
  for (const ProbeRow& row : rows) {
    appendNumber(text, row.time);
    for (double v : row.values) {
      text += ',';
      if (std::isnan(v)) {
        text += "nan";
      } else {
        appendNumber(text, v);
      }
    }
    text += '\n';
  }
  file_.append(text);
}

}  // namespace sph::io
