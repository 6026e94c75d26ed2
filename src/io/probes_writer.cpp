#include "io/probes_writer.hpp"

#include <cerrno>
#include <cmath>
#include <utility>

#include "io/file_error.hpp"

namespace sph::io {

ProbesWriter::ProbesWriter(std::filesystem::path csvFile, const std::vector<std::string>& columns)
    : path_(std::move(csvFile)) {
  errno = 0;
  file_.reset(std::fopen(path_.string().c_str(), "w"));
  if (!file_) throwFileError("open", path_, errno);
  std::string header = "time_s";
  for (const std::string& column : columns) header += "," + column;
  header += "\n";
  errno = 0;
  if (std::fputs(header.c_str(), file_.get()) < 0 || std::fflush(file_.get()) != 0)
    throwFileError("write", path_, errno);
}

void ProbesWriter::append(const std::vector<ProbeRow>& rows) {
  std::FILE* out = file_.get();
  errno = 0;
  for (const ProbeRow& row : rows) {
    bool ok = std::fprintf(out, "%.9g", row.time) > 0;
    for (double v : row.values)
      ok = ok && (std::isnan(v) ? std::fputs(",nan", out) >= 0 : std::fprintf(out, ",%.9g", v) > 0);
    ok = ok && std::fputc('\n', out) != EOF;
    if (!ok) throwFileError("write", path_, errno);
  }
  if (std::fflush(out) != 0) throwFileError("write", path_, errno);
}

}  // namespace sph::io
