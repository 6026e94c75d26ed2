// The little XML the collection readers need: an attribute of an element, its escapes undone,
// and whether a file it names stays inside the collection's folder.
#pragma once

#include <optional>
#include <string>

namespace sph::io {

// The value of attribute `name` in `element` (the text of a start tag after its name), or
// nothing.
std::optional<std::string> xmlAttribute(const std::string& element, const std::string& name);

// `text` with XML's five escapes undone; empty when it holds another `&`.
std::string unescapeXmlAttribute(const std::string& text);

// Whether `relative` names a file inside the folder it is relative to: not empty, not
// absolute, no "..".
bool staysInsideFolder(const std::string& relative);

}  // namespace sph::io
