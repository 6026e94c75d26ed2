#include "scene/scene_schema.hpp"

#include "scene/scene_keys.hpp"

#include <algorithm>
#include <utility>

namespace sph::scene {
namespace {

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbouring characters each cost 1, so "sapcing" is as close to "spacing" as "spacng".
std::size_t editDistance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::size_t> d((n + 1) * (m + 1));
  auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * (m + 1) + j]; };
  for (std::size_t i = 0; i <= n; ++i) at(i, 0) = i;
  for (std::size_t j = 0; j <= m; ++j) at(0, j) = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
      }
    }
  }
  return at(n, m);
}

}  // namespace

const KeySchema* KeySchema::find(const std::string& key) const {
  if (shape != Shape::Object) return nullptr;
  for (const KeySchema& c : children) {
    if (c.name == key) return &c;
  }
  return nullptr;
}

const KeySchema& KeySchema::child(const std::string& key) const {
  const KeySchema* found = find(key);
  if (found == nullptr) throw std::logic_error("scene schema has no key '" + key + "'");
  return *found;
}

const KeySchema& sceneSchema() {
  static const KeySchema schema = schemaOf("", sceneKeys());
  return schema;
}

std::string joinKey(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string joinIndex(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

bool keyWithin(const std::string& inner, const std::string& outer) {
  if (inner.size() == outer.size()) return inner == outer;
  return !outer.empty() && inner.size() > outer.size() &&
         inner.compare(0, outer.size(), outer) == 0 &&
         (inner[outer.size()] == '.' || inner[outer.size()] == '[');
}

std::optional<std::string> nearestKey(const std::string& key, const KeySchema& level) {
  std::optional<std::string> best;
  std::size_t bestDistance = 0;
  for (const KeySchema& candidate : level.children) {
    const std::size_t distance = editDistance(key, candidate.name);
    // About one edit in three characters still reads as a typo; more is a different word.
    const std::size_t tolerance = std::max<std::size_t>(1, candidate.name.size() / 3);
    if (distance <= tolerance && (!best || distance < bestDistance)) {
      best = candidate.name;
      bestDistance = distance;
    }
  }
  return best;
}

namespace {

// Keys that older versions read, and why they are gone: a scene that still names one is told
// so, not offered the nearest key.
struct RemovedKey {
  const char* path;
  const char* why;
};
constexpr RemovedKey kRemovedKeys[] = {
    {"fluid.dfsph.chebyshev",
     "Chebyshev's weights on the density solve were measured and not kept (docs/experiments.md); "
     "delete the key"},
};

}  // namespace

std::string unknownKeyText(const std::string& parentPath, const std::string& key,
                           const KeySchema& level) {
  const std::string path = joinKey(parentPath, key);
  for (const RemovedKey& removed : kRemovedKeys)
    if (path == removed.path) return path + ": removed from sph: " + removed.why;
  std::string text = "unknown key " + path;
  if (const auto suggestion = nearestKey(key, level)) {
    return text + " (did you mean " + joinKey(parentPath, *suggestion) + "?)";
  }
  text += parentPath.empty() ? " (top-level keys are: " : " (keys of " + parentPath + " are: ";
  for (std::size_t i = 0; i < level.children.size(); ++i) {
    text += (i == 0 ? "" : ", ") + level.children[i].name;
  }
  return text + ")";
}

}  // namespace sph::scene
