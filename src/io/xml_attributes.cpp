#include "io/xml_attributes.hpp"

#include <cctype>
#include <cstring>
#include <filesystem>
#include <utility>

namespace sph::io {

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

std::optional<std::string> xmlAttribute(const std::string& element, const std::string& name) {
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

bool staysInsideFolder(const std::string& relative) {
  const std::filesystem::path path(relative);
  if (relative.empty() || path.is_absolute()) return false;
  for (const std::filesystem::path& part : path)
    if (part == "..") return false;
  return true;
}

}  // namespace sph::io
