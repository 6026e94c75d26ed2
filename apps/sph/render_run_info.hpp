// What `sph render` takes from a run's summary.json (its resolved scene): frame rate, particle
// spacing, support radius, domain, and how its fluid looks. A run without one still renders, from
// the frames alone.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "camera.hpp"

namespace sph::cli {

struct RenderRunInfo {
  std::optional<double> fps;
  std::optional<float> spacing;        // fluid.spacing, m
  std::optional<float> supportRadius;  // spacing × fluid.support_ratio: the grid's cell size
  std::optional<render::Box3f> domain;
  std::optional<std::string> look;  // render.look: "liquid" or "particles"
  std::optional<render::Vec3f> liquidColour, absorption;
};

// Reads DIR/summary.json when present. Throws InputError naming the file and the key when it is
// not JSON or a key has the wrong type.
RenderRunInfo readRenderRunInfo(const std::filesystem::path& dir);

}  // namespace sph::cli
