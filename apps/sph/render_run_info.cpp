#include "render_run_info.hpp"

#include <nlohmann/json.hpp>

#include <string>

#include "run_summary.hpp"
#include "sph/error.hpp"

namespace sph::cli {

namespace {

using nlohmann::json;

std::optional<render::Vec3f> point(const json& summary, const char* pointer,
                                   const std::filesystem::path& file) {
  const json::json_pointer at(pointer);
  if (!summary.contains(at)) return std::nullopt;
  const json& value = summary.at(at);
  if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
      !value[2].is_number())
    throw InputError(file.string() + ": key '" + std::string(pointer).substr(1) +
                     "' is not [x, y, z]");
  return render::Vec3f{value[0].get<float>(), value[1].get<float>(), value[2].get<float>()};
}

}  // namespace

RenderRunInfo readRenderRunInfo(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "summary.json";
  RenderRunInfo info;
  const std::optional<json> read = readRunSummary(dir);
  if (!read) return info;
  const json& summary = *read;
  info.fps = summaryNumber(summary, "/scene/output/fps", file);
  if (info.fps && !(*info.fps > 0))
    throw InputError(file.string() + ": key 'scene/output/fps' must be positive");
  if (const auto spacing = summaryNumber(summary, "/scene/fluid/spacing", file)) {
    info.spacing = static_cast<float>(*spacing);
    const double ratio = summaryNumber(summary, "/scene/fluid/support_ratio", file).value_or(2.0);
    info.supportRadius = static_cast<float>(*spacing * ratio);
  }
  const auto min = point(summary, "/scene/domain/min", file);
  const auto max = point(summary, "/scene/domain/max", file);
  if (min && max) info.domain = render::Box3f{*min, *max};
  const json::json_pointer look("/scene/render/look");
  if (summary.contains(look)) {
    if (!summary.at(look).is_string())
      throw InputError(file.string() + ": key 'scene/render/look' is not a string");
    info.look = summary.at(look).get<std::string>();
  }
  info.liquidColour = point(summary, "/scene/render/colour", file);
  info.absorption = point(summary, "/scene/render/absorption", file);
  return info;
}

}  // namespace sph::cli
