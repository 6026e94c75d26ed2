// Checks shared by the scene's readers: names plain and unique, boxes in order, points and boxes
// inside the domain, lengths a spacing or more. Each failure throws InputError naming the key.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_reader.hpp"
#include "sph/scene.hpp"

namespace sph::scene {

// The names of `items` (the scene's array `list` of `what`s): no commas or quotes (they head
// columns and keys of the outputs), none twice.
template <class Desc>
void checkNames(const ReadContext& context, const std::vector<Desc>& items, const char* list,
                const char* what) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string& name = items[i].name;
    const std::string key = joinIndex(list, i) + ".name";
    if (name.empty() || name.find_first_of(",\"\n") != std::string::npos)
      context.fail(key, "expected a name without commas or quotes, got \"" + name + "\"");
    for (std::size_t j = 0; j < i; ++j) {
      if (items[j].name == name)
        context.fail(key, std::string("expected a name no other ") + what + " has, got \"" + name +
                              "\" (also " + joinIndex(list, j) + ")");
    }
  }
}

double lengthOf(const Vec3d& v);
Vec3d cross(const Vec3d& a, const Vec3d& b);

void checkPointInDomain(const ReadContext& context, const Vec3d& x, const std::string& key,
                        const AxisBox& domain);
// `path` names the object holding the box's "min" and "max".
void checkBoxOrder(const ReadContext& context, const AxisBox& box, const std::string& path);
void checkInsideDomain(const ReadContext& context, const AxisBox& box, const std::string& path,
                       const AxisBox& domain);
// A length that must carry particles a spacing apart.
void checkAtLeastSpacing(const ReadContext& context, double value, const std::string& key,
                         double spacing);
// `edge2` (at key) not parallel to `edge1` (at edge1Key).
void checkNotParallel(const ReadContext& context, const Vec3d& edge1, const Vec3d& edge2,
                      const std::string& edge1Key, const std::string& key);

}  // namespace sph::scene
