// The scene's flow in and out: "emitters" and "outlets" checked (scene_keys.cpp reads them).
#pragma once

#include <vector>

#include "scene/scene_reader.hpp"
#include "sph/scene.hpp"

namespace sph::scene {

// Names unique and plain, shapes inside the domain and at least a spacing across, times in
// order, no more than kMaxEmitters and kMaxOutlets.
void checkFlow(const ReadContext& context, const Scene& scene);

}  // namespace sph::scene
