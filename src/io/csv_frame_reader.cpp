// Reads the CSV that csv_frame_writer.cpp writes: a header naming the columns, then one row per
// particle. Columns are found by name, so a spreadsheet that reorders them still reads.
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "sph/io/frame_reader.hpp"
#include "io/frame_reader_support.hpp"

namespace sph::io {

namespace {

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (!fields.empty() && !fields.back().empty() && fields.back().back() == '\r')
    fields.back().pop_back();
  return fields;
}

double parseNumber(const std::string& field, const std::string& column, std::size_t line,
                   const std::filesystem::path& file) {
  const char* begin = field.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (field.empty() || *end != '\0')
    throwBadFrame(file, "line " + std::to_string(line) + ", column '" + column + "': '" + field +
                            "' is not a number");
  return value;
}

// A value a frame's integer or float column can hold: a cast of anything else is undefined.
double requireWithin(double value, double lo, double hi, bool integer, const char* column,
                     std::size_t line, const std::filesystem::path& file) {
  if (!(value >= lo && value <= hi) || (integer && value != std::floor(value))) {
    std::ostringstream text;
    text << "line " << line << ", column '" << column << "': " << value << " is not "
         << (integer ? "an integer" : "a number") << " in [" << lo << ", " << hi << "]";
    throwBadFrame(file, text.str());
  }
  return value;
}

}  // namespace

ParticleFrame readCsvFrame(const std::string& text, const std::filesystem::path& file) {
  std::istringstream lines(text);
  std::string line;
  if (!std::getline(lines, line)) throwBadFrame(file, "empty; expected a CSV header");
  const std::vector<std::string> header = splitFields(line);
  std::map<std::string, std::size_t> column;
  for (std::size_t c = 0; c < header.size(); ++c) column[header[c]] = c;
  const char* const names[] = {"id", "kind", "object", "x",       "y",        "z",
                               "vx", "vy",   "vz",     "density", "pressure", "surface"};
  std::size_t index[12];
  for (int k = 0; k < 12; ++k) {
    const auto found = column.find(names[k]);
    // Surface flags are optional; index past the end marks them absent.
    if (found == column.end() && k != 11)
      throwBadFrame(file, std::string("no column '") + names[k] + "' in the header");
    index[k] = found == column.end() ? header.size() : found->second;
  }

  ParticleFrame frame;
  std::vector<double> v(12);
  for (std::size_t lineNumber = 2; std::getline(lines, line); ++lineNumber) {
    if (line.empty() || line == "\r") continue;
    const std::vector<std::string> fields = splitFields(line);
    if (fields.size() != header.size())
      throwBadFrame(file, "line " + std::to_string(lineNumber) + " has " +
                              std::to_string(fields.size()) + " fields, expected " +
                              std::to_string(header.size()) + " (truncated?)");
    for (int k = 0; k < 12; ++k)
      v[k] = index[k] < fields.size() ? parseNumber(fields[index[k]], names[k], lineNumber, file)
                                      : 0.0;
    const std::size_t i = frame.size();
    // Out-of-range doubles must not reach the casts below (undefined behaviour).
    requireValidKind(v[1] >= 0 && v[1] <= 2 ? static_cast<unsigned>(v[1]) : 255u, i, file);
    requireWithin(v[0], 0, 4294967295.0, true, names[0], lineNumber, file);
    requireWithin(v[2], -1, 2147483647.0, true, names[2], lineNumber, file);
    requireWithin(v[11], 0, 1, true, names[11], lineNumber, file);
    for (int k = 3; k <= 10; ++k)
      requireWithin(v[k], -FLT_MAX, FLT_MAX, false, names[k], lineNumber, file);
    frame.id.push_back(static_cast<std::uint32_t>(v[0]));
    frame.kind.push_back(static_cast<std::uint8_t>(v[1]));
    frame.object.push_back(static_cast<std::int32_t>(v[2]));
    for (int c = 0; c < 3; ++c) {
      frame.position.push_back(static_cast<float>(v[3 + c]));
      frame.velocity.push_back(static_cast<float>(v[6 + c]));
    }
    frame.density.push_back(static_cast<float>(v[9]));
    frame.pressure.push_back(static_cast<float>(v[10]));
    frame.surface.push_back(static_cast<std::uint8_t>(v[11]));
  }
  return frame;
}

}  // namespace sph::io
