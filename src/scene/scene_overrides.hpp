// `--set dotted.key=value` overrides, applied to a scene document before it is validated.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sph::scene {

struct AppliedOverride {
  std::string text;     // as given: "fluid.blocks.0.max=[0.1,0.2,0.1]"
  std::string keyPath;  // as messages show it: "fluid.blocks[0].max"
};

// Applies each override to `document` (a JSON object) in order. Numeric key segments index
// arrays; an index one past the end appends. Missing objects and arrays on the way are
// created. The value is parsed as JSON if it parses, otherwise taken as a string. Keys not in
// the scene schema are rejected with the nearest known key. Returns the overrides whose
// values are still in the document (a later override of the same key or of a key above it
// replaces an earlier one), so that messages can say where a bad value came from.
std::vector<AppliedOverride> applyOverrides(nlohmann::json& document,
                                            const std::vector<std::string>& overrides,
                                            const std::string& sourceName);

}  // namespace sph::scene
