// Typed, checked reads from a scene document. Every failure throws sph::InputError with the
// source name, the dotted key and what was expected; a value that came from `--set` says so.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_overrides.hpp"
#include "scene/scene_schema.hpp"
#include "sph/scene.hpp"

namespace sph::scene {

// A JSON value as a message quotes it, shortened if long.
std::string describeValue(const nlohmann::json& value);
std::string formatVec3(const Vec3d& v);

class ReadContext {
 public:
  ReadContext(std::string sourceName, std::vector<AppliedOverride> overrides);

  // Throws "<source>: <keyPath>: <text>", naming the overrides that set `keyPath`, a key
  // above it or below it, or any of `relatedPaths` (the other keys a cross-check read).
  [[noreturn]] void fail(const std::string& keyPath, const std::string& text,
                         const std::vector<std::string>& relatedPaths = {}) const;
  [[noreturn]] void failUnknownKey(const std::string& parentPath, const std::string& key,
                                   const KeySchema& level) const;

 private:
  std::string attribution(const std::vector<std::string>& paths) const;

  std::string sourceName_;
  std::vector<AppliedOverride> overrides_;
};

// Accepted numbers: an interval, possibly open at either end, possibly unbounded above.
struct NumberRule {
  double lo;
  double hi;
  bool loOpen;
  bool hiOpen;

  bool accepts(double v) const {
    return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
  }
  std::string describe() const;  // "a positive number", "a number in (0, 1]"
};

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr NumberRule kPositive{0, kInfinity, true, true};
inline constexpr NumberRule kNonNegative{0, kInfinity, false, true};
inline constexpr NumberRule kClosedUnit{0, 1, false, false};  // [0, 1]
inline constexpr NumberRule kUnitStep{0, 1, true, false};     // (0, 1]
inline constexpr NumberRule kOpenUnit{0, 1, true, true};      // (0, 1)
// Physical ranges, so that what validate accepts, run runs: a particle spacing from a micron to
// 100 m (below, a lattice index overflows and nothing is sampled), a time step from a
// nanosecond to 10 s (below, time stops advancing in double precision within a run), frames
// and probe samples no faster than a camera or a sensor takes them.
inline constexpr NumberRule kSpacing{1e-6, 100, false, false};
inline constexpr NumberRule kTimeStep{1e-9, 10, false, false};
inline constexpr NumberRule kDuration{0, 1e6, true, false};
inline constexpr NumberRule kFrameRate{0, 1e5, true, false};
inline constexpr NumberRule kSampleRate{0, 1e7, true, false};
inline constexpr NumberRule kScale{0, 1e3, true, false};  // a mesh's, on coordinates ≤ 1e6
// Densities from a light gas's to past osmium's, kg/m³; speeds and sizes far past any scene's
// and short of those that overflow a step or a particle count.
inline constexpr NumberRule kDensity{1e-3, 1e5, false, false};
inline constexpr NumberRule kSpeed{0, 1e4, true, false};            // m/s
inline constexpr NumberRule kLength{0, 1e4, false, false};          // an object's size, m
inline constexpr NumberRule kSurfaceTension{0, 100, false, false};  // N/m (water: 0.072)
// The largest magnitude of a vector's coordinates: positions (as a mesh's vertices), velocities
// (m/s), angular velocities (rad/s) and accelerations (m/s², gravity's up to 1,000 g).
inline constexpr double kLargestCoordinate = 1e6;
inline constexpr double kLargestVelocity = 1e4;
inline constexpr double kLargestSpin = 1e4;
inline constexpr double kLargestAcceleration = 1e4;

// Reads the keys of one JSON object. Constructing it checks that the value is an object and
// that every key in it is in the schema. A reader of an absent object gives every default.
class ObjectReader {
 public:
  ObjectReader(const ReadContext& context, const nlohmann::json* object, std::string path,
               const KeySchema& schema);

  const std::string& path() const { return path_; }
  std::string keyPath(const std::string& key) const { return joinKey(path_, key); }

  ObjectReader object(const std::string& key) const;
  ObjectReader requiredObject(const std::string& key) const;
  // The elements of an array of objects; absent gives none unless `required`.
  std::vector<ObjectReader> objectArray(const std::string& key, bool required, bool nonEmpty) const;

  bool has(const std::string& key) const { return find(key) != nullptr; }
  const ReadContext& context() const { return *context_; }

  std::string string(const std::string& key, const std::string& fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  double number(const std::string& key, double fallback, const NumberRule& rule) const;
  // Absent or null gives nullopt.
  std::optional<double> optionalNumber(const std::string& key, const NumberRule& rule) const;
  int integer(const std::string& key, int fallback, int lo, int hi) const;
  // Each coordinate at most `largest` in magnitude.
  Vec3d vec3(const std::string& key, const Vec3d& fallback,
             double largest = kLargestCoordinate) const;
  Vec3d requiredVec3(const std::string& key, double largest = kLargestCoordinate) const;
  // Each coordinate within [lo, hi].
  Vec3d vec3Within(const std::string& key, const Vec3d& fallback, double lo, double hi) const;

  template <class Enum, std::size_t N>
  Enum choice(const std::string& key, Enum fallback, const NamedValue<Enum> (&names)[N]) const;

 private:
  const nlohmann::json* find(const std::string& key) const;
  const nlohmann::json& require(const std::string& key) const;
  double checkedNumber(const nlohmann::json& value, const std::string& key, const NumberRule& rule,
                       const char* orWhat) const;
  Vec3d checkedVec3(const nlohmann::json& value, const std::string& key, double largest) const;

  const ReadContext* context_;
  const nlohmann::json* object_;
  std::string path_;
  const KeySchema* schema_;
};

template <class Enum, std::size_t N>
Enum ObjectReader::choice(const std::string& key, Enum fallback,
                          const NamedValue<Enum> (&names)[N]) const {
  const nlohmann::json* value = find(key);
  if (value == nullptr) return fallback;
  if (value->is_string()) {
    for (const auto& named : names) {
      if (value->get_ref<const std::string&>() == named.name) return named.value;
    }
  }
  std::string expected = "expected one of ";
  for (std::size_t i = 0; i < N; ++i) {
    expected += std::string(i == 0 ? "" : ", ") + "\"" + names[i].name + "\"";
  }
  context_->fail(keyPath(key), expected + ", got " + describeValue(*value));
}

}  // namespace sph::scene
