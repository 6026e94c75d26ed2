// The scene's flow in and out: "emitters" and "outlets" read and checked.
#pragma once

#include <vector>

#include "io/scene_reader.hpp"
#include "sph/scene.hpp"

namespace sph::io {

std::vector<EmitterDesc> readEmitters(const ObjectReader& root);
std::vector<OutletDesc> readOutlets(const ObjectReader& root);
// Names unique and plain, shapes inside the domain and at least a spacing across, times in
// order, no more than kMaxEmitters and kMaxOutlets.
void checkFlow(const ReadContext& context, const Scene& scene);

}  // namespace sph::io
