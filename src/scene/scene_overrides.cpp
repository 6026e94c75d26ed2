#include "scene/scene_overrides.hpp"

#include "scene/json_input.hpp"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <optional>

#include "scene/json_input.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_schema.hpp"
#include "sph/error.hpp"

namespace sph::scene {
namespace {

using nlohmann::json;

// One step of an override's key: a key of an object, or an index into an array.
struct KeyStep {
  std::string key;
  std::optional<std::size_t> index;
  bool intoVector = false;  // an index into an array of numbers, whose length is fixed
};

// "--set fluid.spacing=x", shortened past 80 characters: a message quotes, not dumps.
std::string quoted(const std::string& text) {
  constexpr std::size_t kLongest = 80;
  return "--set " + (text.size() > kLongest ? text.substr(0, kLongest - 3) + "..." : text);
}

class OverrideError {
 public:
  OverrideError(const std::string& sourceName, const std::string& text)
      : where_(sourceName + ": " + quoted(text)) {}
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(where_ + ": " + problem);
  }
  const std::string& where() const { return where_; }

 private:
  std::string where_;
};

bool isUtf8(const std::string& text) {
  try {
    json(text).dump();
    return true;
  } catch (const json::type_error&) {
    return false;
  }
}

std::string trim(const std::string& s) {
  const auto notSpace = [](unsigned char c) { return !std::isspace(c); };
  const auto begin = std::find_if(s.begin(), s.end(), notSpace);
  const auto end = std::find_if(s.rbegin(), s.rend(), notSpace).base();
  return begin < end ? std::string(begin, end) : std::string();
}

std::optional<std::size_t> parseIndex(const std::string& segment) {
  // Nine digits are far more elements than a scene has, and cannot overflow.
  if (segment.empty() || segment.size() > 9) return std::nullopt;
  std::size_t index = 0;
  for (const char c : segment) {
    if (c < '0' || c > '9') return std::nullopt;
    index = index * 10 + static_cast<std::size_t>(c - '0');
  }
  return index;
}

// Splits `a.b.0.c` and checks each step against the schema; returns the steps and sets
// `keyPath` to the key as messages write it (`a.b[0].c`).
std::vector<KeyStep> resolveKey(const std::string& dotted, const OverrideError& error,
                                std::string& keyPath) {
  std::vector<KeyStep> steps;
  const KeySchema* level = &sceneSchema();
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = dotted.find('.', start);
    const std::string segment = dotted.substr(start, dot == std::string::npos ? dot : dot - start);
    if (segment.empty()) error.fail("expected dotted.key=value, with no empty key segment");
    if (level->shape == KeySchema::Shape::Object) {
      const KeySchema* next = level->find(segment);
      if (next == nullptr) error.fail(unknownKeyText(keyPath, segment, *level));
      steps.push_back({segment, std::nullopt, false});
      keyPath = joinKey(keyPath, segment);
      level = next;
    } else if (level->shape == KeySchema::Shape::Array) {
      const std::optional<std::size_t> index = parseIndex(segment);
      if (!index) {
        error.fail(keyPath + " is an array: expected an index (0, 1, ...) after it, got \"" +
                   segment + "\"");
      }
      level = &level->element();
      steps.push_back({segment, index, level->shape == KeySchema::Shape::Value});
      keyPath = joinIndex(keyPath, *index);
    } else {
      error.fail(keyPath + " holds a single value and has no key \"" + segment + "\"");
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return steps;
}

// Walks the document along `steps`, creating what is missing, and stores `value` at the end.
void store(json& document, const std::vector<KeyStep>& steps, json value,
           const OverrideError& error) {
  json* node = &document;
  std::string path;
  std::string dotted;
  for (const KeyStep& step : steps) {
    if (step.index) {
      if (node->is_null() && step.intoVector) {
        error.fail(path + " is not in the scene, so it has no element " + step.key +
                   "; set the whole array instead, as in " + dotted + "=[x,y,z]");
      }
      if (node->is_null()) *node = json::array();
      if (!node->is_array()) {
        error.fail(path + " is not an array in the scene (it is " + describeValue(*node) + ")");
      }
      // Arrays of objects grow by one at a time; vectors keep their length.
      const std::size_t end = step.intoVector ? node->size() : node->size() + 1;
      if (*step.index >= end) {
        error.fail("index " + step.key + " is past the end of " + path + ", which has " +
                   std::to_string(node->size()) + " elements" +
                   (step.intoVector ? "" : " (an index equal to the count appends)"));
      }
      if (*step.index == node->size()) node->push_back(nullptr);
      node = &(*node)[*step.index];
      path = joinIndex(path, *step.index);
      dotted += "." + step.key;
    } else {
      if (node->is_null()) *node = json::object();
      if (!node->is_object()) {
        error.fail(path + " is not an object in the scene (it is " + describeValue(*node) + ")");
      }
      node = &(*node)[step.key];
      path = joinKey(path, step.key);
      dotted = joinKey(dotted, step.key);
    }
  }
  *node = std::move(value);
}

}  // namespace

std::vector<AppliedOverride> applyOverrides(json& document,
                                            const std::vector<std::string>& overrides,
                                            const std::string& sourceName) {
  std::vector<AppliedOverride> applied;
  for (const std::string& text : overrides) {
    const OverrideError error(sourceName, text);
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos) error.fail("expected dotted.key=value");
    const std::string key = trim(text.substr(0, equals));
    const std::string valueText = trim(text.substr(equals + 1));

    std::string keyPath;
    const std::vector<KeyStep> steps = resolveKey(key, error, keyPath);
    std::optional<json> parsed = parseJsonIfValid(valueText, error.where());
    json value = parsed ? std::move(*parsed) : json(valueText);  // `format=ply` needs no quotes
    // A scene's text is UTF-8 (the JSON parser checks a file's); bytes that are not would fail
    // later, wherever the value is printed.
    if (!parsed && !isUtf8(valueText)) error.fail("expected UTF-8 text");
    store(document, steps, std::move(value), error);

    // This value replaces whatever earlier overrides put at or below the same key.
    applied.erase(std::remove_if(applied.begin(), applied.end(),
                                 [&](const AppliedOverride& earlier) {
                                   return keyWithin(earlier.keyPath, keyPath);
                                 }),
                  applied.end());
    applied.push_back({text, keyPath});
  }
  return applied;
}

}  // namespace sph::scene
