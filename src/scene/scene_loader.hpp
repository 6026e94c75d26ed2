// Scene files: JSON in, a checked sph::Scene out, and the resolved scene back to JSON.
// The schema is the one README.md documents under Scenes; scene_keys.cpp declares every key.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "sph/scene.hpp"

namespace sph::scene {

// Reads, overrides and validates a scene file. `overrides` are `--set` strings,
// `dotted.key=value`, applied in order before validation. Throws sph::InputError naming the
// file, the key and what was expected.
Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// What loadScene does after reading the file. `sourceName` names the document in messages
// and becomes Scene::sourcePath.
Scene parseScene(const nlohmann::json& document, const std::string& sourceName,
                 const std::vector<std::string>& overrides = {});

// Throws sph::InputError, as parseScene would, where `scene` breaks a key's limits or a check
// across keys: what loadScene refuses, Simulation refuses too. Returns the scene with its
// unnamed walls, objects, probes, emitters and outlets named as the loader names them.
Scene validateScene(const Scene& scene);

// The fully resolved scene in the same schema: every key, defaults included, unset optional
// values as null. parseScene(sceneToJson(s), ...) gives back the same values.
nlohmann::json sceneToJson(const Scene& scene);

}  // namespace sph::scene
