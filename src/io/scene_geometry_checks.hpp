// Checks of a scene's geometry shared by its readers: boxes in order, points and boxes inside
// the domain, lengths a spacing or more. Each failure throws InputError naming the key.
#pragma once

#include <string>

#include "io/scene_reader.hpp"
#include "sph/scene.hpp"

namespace sph::io {

AxisBox readBox(const ObjectReader& in);  // "min" and "max", both required

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

}  // namespace sph::io
