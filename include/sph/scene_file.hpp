// Scene files: the JSON documented in the README's scene reference, read into a checked
// sph::Scene, and a scene written back as JSON.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sph/scene.hpp"

namespace sph {

// Reads a scene file, applies `overrides` (`dotted.key=value`, as `sph run --set`) in order,
// and checks the result. Throws sph::InputError naming the file, the key and what was
// expected.
Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// The same from JSON text; `sourceName` names the document in messages and becomes
// Scene::sourcePath (a relative mesh file is found beside it).
Scene parseScene(const std::string& jsonText, const std::string& sourceName,
                 const std::vector<std::string>& overrides = {});

// Checks a scene built in code as loadScene checks a file: every key's limits and the checks
// across keys. Throws sph::InputError naming the key and what was expected; returns the scene
// with unnamed walls, objects, probes, emitters and outlets named ("wall0"). A Simulation
// checks its scene this way before anything else.
Scene validateScene(const Scene& scene);

// The fully resolved scene as JSON text: every key, defaults included, unset optional values as
// null. parseScene of it gives back the same scene.
std::string sceneToJsonText(const Scene& scene);

}  // namespace sph
