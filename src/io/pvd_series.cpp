#include "sph/io/pvd_series.hpp"

#include <ostream>
#include <utility>

#include "sph/io/frame_writer.hpp"

namespace sph::io {
namespace {

// File names go into an XML attribute; a name with & or " must not break the document.
std::string escapeXmlAttribute(const std::string& text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

}  // namespace

PvdSeries::PvdSeries(std::filesystem::path pvdFile) : pvdFile_(std::move(pvdFile)) {}

PvdSeries::PvdSeries(std::filesystem::path pvdFile,
                     std::vector<std::pair<double, std::string>> frames)
    : pvdFile_(std::move(pvdFile)) {
  for (auto& [time, file] : frames) entries_.push_back({time, std::move(file)});
}

std::vector<std::pair<double, std::string>> PvdSeries::frames() const {
  std::vector<std::pair<double, std::string>> out;
  for (const Entry& e : entries_) out.emplace_back(e.time, e.file);
  return out;
}

void PvdSeries::add(double time, const std::string& relativeFile) {
  entries_.push_back({time, escapeXmlAttribute(relativeFile)});
  try {
    writeFileAtomically(pvdFile_, [&](std::ostream& out) {
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          << "  <Collection>\n";
      for (const Entry& entry : entries_) {
        out << "    <DataSet timestep=\"" << formatDouble(entry.time)
            << "\" group=\"\" part=\"0\" file=\"" << entry.file << "\"/>\n";
      }
      out << "  </Collection>\n</VTKFile>\n";
    });
  } catch (...) {
    // Keep the series and the file on disk in agreement so a retried add does not list twice.
    entries_.pop_back();
    throw;
  }
}

}  // namespace sph::io
