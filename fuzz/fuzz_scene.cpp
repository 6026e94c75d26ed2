// Any bytes as a scene file: either a checked scene or an InputError, and a scene that loads
// writes out (sceneToJson) to a document that loads again to the same JSON.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "scene/json_input.hpp"
#include "scene/scene_loader.hpp"
#include "sph/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const nlohmann::json document = sph::scene::parseJson(in, "fuzz.json");
    const sph::Scene scene = sph::scene::parseScene(document, "fuzz.json");
    const nlohmann::json written = sph::scene::sceneToJson(scene);
    if (sph::scene::sceneToJson(sph::scene::parseScene(written, "written.json")) != written)
      std::abort();
  } catch (const sph::InputError&) {
  }
  return 0;
}
