// A finished run's summary.json (its resolved scene among the rest), for the commands that work
// on a run's directory afterwards: sph render and sph surface.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace sph::cli {

// DIR/summary.json, or none when the run has none. Throws InputError naming the file when it is
// not a JSON object.
std::optional<nlohmann::json> readRunSummary(const std::filesystem::path& dir);

// The number at the JSON pointer ("/scene/fluid/spacing"), or none when absent or null. Throws
// InputError naming `file` and the key when it is something else.
std::optional<double> summaryNumber(const nlohmann::json& summary, const char* pointer,
                                    const std::filesystem::path& file);

}  // namespace sph::cli
