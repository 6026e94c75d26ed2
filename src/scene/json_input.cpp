#include "scene/json_input.hpp"

#include <set>
#include <utility>
#include <vector>

#include "sph/error.hpp"

namespace sph::scene {

namespace {

using nlohmann::json;

[[noreturn]] void failTooDeep(const std::string& where) {
  throw InputError(where + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                   " levels; no scene needs more than a few");
}

// Follows the parser's events to name where it is ("fluid.blocks[1]") and to see every key of
// each object being read.
class Watcher {
 public:
  explicit Watcher(std::string where) : where_(std::move(where)) {}

  bool operator()(int depth, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (depth >= kMaxJsonDepth) failTooDeep(where_);
        open_.push_back({event == json::parse_event_t::array_start, {}, {}, 0});
        break;
      case json::parse_event_t::key: {
        Level& level = open_.back();
        level.key = parsed.get<std::string>();
        if (!level.keys.insert(level.key).second)
          throw InputError(where_ + ": " + path() + ": the key appears twice in one object");
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        open_.pop_back();
        elementDone();
        break;
      case json::parse_event_t::value:
        elementDone();
        break;
    }
    return true;
  }

 private:
  struct Level {
    bool array;
    std::string key;  // objects: the key being read
    std::set<std::string> keys;
    std::size_t index;  // arrays: the element being read
  };

  void elementDone() {
    if (!open_.empty() && open_.back().array) ++open_.back().index;
  }
  std::string path() const {
    std::string out;
    for (const Level& level : open_) {
      if (level.array)
        out += "[" + std::to_string(level.index) + "]";
      else
        out += (out.empty() ? "" : ".") + level.key;
    }
    return out;
  }

  std::string where_;
  std::vector<Level> open_;
};

// nlohmann's messages start with "[json.exception.parse_error.101] "; the rest is for people.
std::string withoutExceptionTag(const std::string& message) {
  if (message.rfind("[json.exception.", 0) == 0) {
    const std::size_t end = message.find("] ");
    if (end != std::string::npos) return message.substr(end + 2);
  }
  return message;
}

template <class Input>
json parseWatched(Input&& input, const std::string& where) {
  try {
    return json::parse(std::forward<Input>(input), Watcher(where));
  } catch (const json::exception& e) {  // parse_error, or out_of_range for 1e999
    throw InputError(where + ": invalid JSON: " + withoutExceptionTag(e.what()));
  }
}

}  // namespace

json parseJson(std::istream& in, const std::string& sourceName) {
  return parseWatched(in, sourceName);
}

std::optional<json> parseJsonIfValid(const std::string& text, const std::string& where) {
  if (!json::accept(text)) return std::nullopt;  // accept() checks syntax without recursing
  return parseWatched(text, where);
}

void checkJsonDepth(const json& document, const std::string& where) {
  std::vector<std::pair<const json*, int>> pending{{&document, 1}};
  while (!pending.empty()) {
    const auto [value, depth] = pending.back();
    pending.pop_back();
    if (!value->is_structured()) continue;
    if (depth > kMaxJsonDepth) failTooDeep(where);
    for (const json& element : *value) pending.push_back({&element, depth + 1});
  }
}

}  // namespace sph::scene
