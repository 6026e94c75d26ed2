#include "io/pvd_reader.hpp"

#include <cctype>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "sph/error.hpp"

namespace sph::io {

namespace {

std::string unescapeXmlAttribute(const std::string& text) {
  std::string plain;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '&') {
      plain += text[k];
      continue;
    }
    bool known = false;
    for (const auto& [entity, c] : {std::pair<const char*, char>{"&amp;", '&'},
                                    {"&lt;", '<'},
                                    {"&gt;", '>'},
                                    {"&quot;", '"'},
                                    {"&apos;", '\''}}) {
      if (text.compare(k, std::strlen(entity), entity) == 0) {
        plain += c;
        k += std::strlen(entity) - 1;
        known = true;
        break;
      }
    }
    if (!known) return {};
  }
  return plain;
}

// The value of attribute `name` in the element text `element` (between "<DataSet" and its
// end), or nothing.
std::optional<std::string> attribute(const std::string& element, const std::string& name) {
  for (std::size_t at = element.find(name); at != std::string::npos;
       at = element.find(name, at + 1)) {
    const bool starts = at == 0 || std::isspace(static_cast<unsigned char>(element[at - 1]));
    std::size_t k = at + name.size();
    while (k < element.size() && std::isspace(static_cast<unsigned char>(element[k]))) ++k;
    if (!starts || k >= element.size() || element[k] != '=') continue;
    ++k;
    while (k < element.size() && std::isspace(static_cast<unsigned char>(element[k]))) ++k;
    if (k >= element.size() || (element[k] != '"' && element[k] != '\'')) return std::nullopt;
    const char quote = element[k];
    const std::size_t end = element.find(quote, k + 1);
    if (end == std::string::npos) return std::nullopt;
    return element.substr(k + 1, end - k - 1);
  }
  return std::nullopt;
}

[[noreturn]] void refusePvd(const std::filesystem::path& file, const std::string& why) {
  throw InputError(file.string() + ": " + why);
}

}  // namespace

std::vector<std::pair<double, std::string>> readPvd(const std::string& bytes,
                                                    const std::filesystem::path& file) {
  if (bytes.find("<VTKFile") == std::string::npos || bytes.find("Collection") == std::string::npos)
    refusePvd(file, "not a VTK collection (.pvd): no <VTKFile type=\"Collection\">");
  std::vector<std::pair<double, std::string>> frames;
  for (std::size_t at = bytes.find("<DataSet"); at != std::string::npos;
       at = bytes.find("<DataSet", at + 1)) {
    const std::size_t end = bytes.find('>', at);
    if (end == std::string::npos) refusePvd(file, "a DataSet element is not closed");
    const std::string element = bytes.substr(at + 8, end - at - 8);
    const std::string which = "DataSet " + std::to_string(frames.size() + 1);
    const std::optional<std::string> time = attribute(element, "timestep");
    const std::optional<std::string> name = attribute(element, "file");
    if (!time || !name) refusePvd(file, which + ": expected a timestep and a file");
    double t = 0.0;
    std::size_t used = 0;
    try {
      t = std::stod(*time, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != time->size() || !std::isfinite(t))
      refusePvd(file, which + ": timestep \"" + time->substr(0, 40) + "\" is not a number");
    const std::string relative = unescapeXmlAttribute(*name);
    const std::filesystem::path path(relative);
    bool escapes = relative.empty() || path.is_absolute();
    for (const std::filesystem::path& part : path) escapes = escapes || part == "..";
    if (escapes)
      refusePvd(file, which + ": file \"" + name->substr(0, 80) +
                          "\" is not a file inside the collection's folder");
    frames.emplace_back(t, relative);
  }
  if (frames.empty()) refusePvd(file, "lists no DataSet (no frames)");
  return frames;
}

}  // namespace sph::io
