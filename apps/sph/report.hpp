// What the commands print and what summary.json holds.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sph/simulation.hpp"

namespace sph::cli {

// The derived values (Meteer 2011, §8.1), each marked derived or set by the scene.
void printCalibration(std::FILE* out, const Simulation& sim);

nlohmann::json calibrationJson(const Calibration& c);
nlohmann::json statsJson(const FrameStats& s);
nlohmann::json objectsJson(const std::vector<ObjectStats>& objects);
// Emitters' or outlets' fluid since the start: name, particles, mass_kg.
nlohmann::json flowJson(const std::vector<FlowStats>& flows);

const char* backendName();
const char* formatName(FrameFormat format);

}  // namespace sph::cli
