// JSON from users, read defensively: nesting no scene needs is refused before anything recurses
// into it, and a key given twice in one object is an error, not a silent "last one wins".
#pragma once

#include <istream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace sph::scene {

// Deeper than any scene (the deepest key, objects[].deformable.pinned[].min[], sits 5 levels
// down), shallow enough that copying and printing a document never exhausts the stack.
inline constexpr int kMaxJsonDepth = 32;

// Parses `in` (named `sourceName` in messages). Throws InputError: "<source>: invalid JSON: …",
// "<source>: <key>: the key appears twice in one object", or "<source>: JSON nested deeper than
// 32 levels (…)".
nlohmann::json parseJson(std::istream& in, const std::string& sourceName);
// The same for a string that may not be JSON at all (`--set output.format=ply`): none then;
// `where` prefixes messages ("scene.json: --set 'a=b'").
std::optional<nlohmann::json> parseJsonIfValid(const std::string& text, const std::string& where);

// Throws InputError ("<where>: JSON nested deeper than 32 levels") for a document built
// elsewhere, without recursing into it.
void checkJsonDepth(const nlohmann::json& document, const std::string& where);

}  // namespace sph::scene
