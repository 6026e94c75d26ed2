#include "io/pvd_reader.hpp"

#include <cctype>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "io/xml_attributes.hpp"
#include "sph/error.hpp"

namespace sph::io {

namespace {

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
    const std::optional<std::string> time = xmlAttribute(element, "timestep");
    const std::optional<std::string> name = xmlAttribute(element, "file");
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
    if (!staysInsideFolder(relative))
      refusePvd(file, which + ": file \"" + name->substr(0, 80) +
                          "\" is not a file inside the collection's folder");
    frames.emplace_back(t, relative);
  }
  if (frames.empty()) refusePvd(file, "lists no DataSet (no frames)");
  return frames;
}

}  // namespace sph::io
