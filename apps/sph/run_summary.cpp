#include "run_summary.hpp"

#include <fstream>
#include <string>

#include "sph/error.hpp"

namespace sph::cli {

std::optional<nlohmann::json> readRunSummary(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "summary.json";
  std::ifstream in(file);
  if (!in) return std::nullopt;
  nlohmann::json summary;
  try {
    summary = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not valid JSON: " + e.what());
  }
  if (!summary.is_object()) throw InputError(file.string() + ": expected a JSON object");
  return summary;
}

std::optional<double> summaryNumber(const nlohmann::json& summary, const char* pointer,
                                    const std::filesystem::path& file) {
  const nlohmann::json::json_pointer at(pointer);
  if (!summary.contains(at) || summary.at(at).is_null()) return std::nullopt;
  const nlohmann::json& value = summary.at(at);
  if (!value.is_number())
    throw InputError(file.string() + ": key '" + std::string(pointer).substr(1) +
                     "' is not a number");
  return value.get<double>();
}

}  // namespace sph::cli
