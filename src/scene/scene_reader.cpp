#include "scene/scene_reader.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include "sph/error.hpp"

namespace sph::scene {

using nlohmann::json;

std::string describeValue(const json& value) {
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    return formatNumber(value.get<double>());
  }
  constexpr std::size_t kMaxLength = 60;
  // Replacement characters for bytes that are not UTF-8: a message must never fail to print.
  std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > kMaxLength) text = text.substr(0, kMaxLength - 3) + "...";
  return text;
}

std::string formatVec3(const Vec3d& v) {
  return "[" + formatNumber(v[0]) + ", " + formatNumber(v[1]) + ", " + formatNumber(v[2]) + "]";
}

std::string NumberRule::describe() const {
  if (hi == kInfinity && lo == 0) return loOpen ? "a positive number" : "a non-negative number";
  return std::string("a number in ") + (loOpen ? "(" : "[") + formatNumber(lo) + ", " +
         formatNumber(hi) + (hiOpen ? ")" : "]");
}

ReadContext::ReadContext(std::string sourceName, std::vector<AppliedOverride> overrides)
    : sourceName_(std::move(sourceName)), overrides_(std::move(overrides)) {}

void ReadContext::fail(const std::string& keyPath, const std::string& text,
                       const std::vector<std::string>& relatedPaths) const {
  std::vector<std::string> paths = relatedPaths;
  paths.push_back(keyPath);
  const std::string where = keyPath.empty() ? "" : keyPath + ": ";
  throw InputError(sourceName_ + ": " + where + text + attribution(paths));
}

void ReadContext::failUnknownKey(const std::string& parentPath, const std::string& key,
                                 const KeySchema& level) const {
  throw InputError(sourceName_ + ": " + unknownKeyText(parentPath, key, level) +
                   attribution({joinKey(parentPath, key)}));
}

std::string ReadContext::attribution(const std::vector<std::string>& paths) const {
  std::string text;
  for (const AppliedOverride& applied : overrides_) {
    for (const std::string& path : paths) {
      if (keyWithin(path, applied.keyPath) || keyWithin(applied.keyPath, path)) {
        text += (text.empty() ? " (from --set " : ", --set ") + applied.text;
        break;
      }
    }
  }
  return text.empty() ? text : text + ")";
}

ObjectReader::ObjectReader(const ReadContext& context, const json* object, std::string path,
                           const KeySchema& schema)
    : context_(&context), object_(object), path_(std::move(path)), schema_(&schema) {
  if (object_ == nullptr) return;
  if (!object_->is_object()) {
    context_->fail(path_, "expected an object, got " + describeValue(*object_));
  }
  for (const auto& item : object_->items()) {
    if (schema_->find(item.key()) == nullptr) context_->failUnknownKey(path_, item.key(), *schema_);
  }
}

const json* ObjectReader::find(const std::string& key) const {
  if (object_ == nullptr) return nullptr;
  const auto it = object_->find(key);
  return it == object_->end() ? nullptr : &*it;
}

const json& ObjectReader::require(const std::string& key) const {
  const json* value = find(key);
  if (value == nullptr) context_->fail(keyPath(key), "required key is missing");
  return *value;
}

ObjectReader ObjectReader::object(const std::string& key) const {
  return ObjectReader(*context_, find(key), keyPath(key), schema_->child(key));
}

ObjectReader ObjectReader::requiredObject(const std::string& key) const {
  return ObjectReader(*context_, &require(key), keyPath(key), schema_->child(key));
}

std::vector<ObjectReader> ObjectReader::objectArray(const std::string& key, bool required,
                                                    bool nonEmpty) const {
  const json* array = required ? &require(key) : find(key);
  if (array == nullptr) return {};
  if (!array->is_array() || (nonEmpty && array->empty())) {
    context_->fail(keyPath(key), std::string("expected ") + (nonEmpty ? "a non-empty" : "an") +
                                     " array of objects, got " + describeValue(*array));
  }
  const KeySchema& element = schema_->child(key).element();
  std::vector<ObjectReader> readers;
  for (std::size_t i = 0; i < array->size(); ++i) {
    readers.emplace_back(*context_, &(*array)[i], joinIndex(keyPath(key), i), element);
  }
  return readers;
}

std::string ObjectReader::string(const std::string& key, const std::string& fallback) const {
  const json* value = find(key);
  if (value == nullptr) return fallback;
  if (!value->is_string()) {
    context_->fail(keyPath(key), "expected a string, got " + describeValue(*value));
  }
  return value->get<std::string>();
}

bool ObjectReader::boolean(const std::string& key, bool fallback) const {
  const json* value = find(key);
  if (value == nullptr) return fallback;
  if (!value->is_boolean()) {
    context_->fail(keyPath(key), "expected true or false, got " + describeValue(*value));
  }
  return value->get<bool>();
}

double ObjectReader::checkedNumber(const json& value, const std::string& key,
                                   const NumberRule& rule, const char* orWhat) const {
  if (value.is_number()) {
    const double v = value.get<double>();
    if (std::isfinite(v) && rule.accepts(v)) return v;
  }
  context_->fail(keyPath(key),
                 "expected " + rule.describe() + orWhat + ", got " + describeValue(value));
}

double ObjectReader::number(const std::string& key, double fallback, const NumberRule& rule) const {
  const json* value = find(key);
  return value == nullptr ? fallback : checkedNumber(*value, key, rule, "");
}

std::optional<double> ObjectReader::optionalNumber(const std::string& key,
                                                   const NumberRule& rule) const {
  const json* value = find(key);
  if (value == nullptr || value->is_null()) return std::nullopt;
  return checkedNumber(*value, key, rule, " or null");
}

int ObjectReader::integer(const std::string& key, int fallback, int lo, int hi) const {
  const json* value = find(key);
  if (value == nullptr) return fallback;
  // 2.0 is accepted as 2: JSON writers do not always keep the difference.
  if (value->is_number()) {
    const double v = value->get<double>();
    if (v >= lo && v <= hi && v == std::floor(v)) return static_cast<int>(v);
  }
  context_->fail(keyPath(key), "expected an integer in [" + std::to_string(lo) + ", " +
                                   std::to_string(hi) + "], got " + describeValue(*value));
}

Vec3d ObjectReader::checkedVec3(const json& value, const std::string& key, double largest) const {
  bool ok = value.is_array() && value.size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i) {
    ok = value[i].is_number() && std::isfinite(value[i].get<double>());
  }
  if (!ok)
    context_->fail(keyPath(key), "expected an array of 3 numbers, got " + describeValue(value));
  for (std::size_t i = 0; i < 3; ++i)
    if (!(std::abs(value[i].get<double>()) <= largest))
      context_->fail(keyPath(key), "expected 3 numbers within ±" + formatNumber(largest) +
                                       ", got " + describeValue(value));
  return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
}

Vec3d ObjectReader::vec3(const std::string& key, const Vec3d& fallback, double largest) const {
  const json* value = find(key);
  return value == nullptr ? fallback : checkedVec3(*value, key, largest);
}

Vec3d ObjectReader::vec3Within(const std::string& key, const Vec3d& fallback, double lo,
                               double hi) const {
  const json* value = find(key);
  if (value == nullptr) return fallback;
  const Vec3d v = checkedVec3(*value, key, kLargestCoordinate);
  for (double c : v)
    if (!(c >= lo && c <= hi))
      context_->fail(keyPath(key), "expected 3 numbers from " + formatNumber(lo) + " to " +
                                       formatNumber(hi) + ", got " + describeValue(*value));
  return v;
}

Vec3d ObjectReader::requiredVec3(const std::string& key, double largest) const {
  return checkedVec3(require(key), key, largest);
}

}  // namespace sph::scene
