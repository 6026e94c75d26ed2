// The sphere the viewer's user drags through the fluid (a kinematic object added to the scene,
// parked just outside the domain until grabbed), and the geometry of grabbing it or any other
// kinematic object, such as the artery's clamps.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "camera.hpp"
#include "sph/scene.hpp"

namespace sph::view {

inline constexpr const char* kProbeName = "probe";

// Adds the probe (radius 3 fluid spacings) above the domain's top face, clear of everything.
// Returns its initial centre.
Vec3d addProbe(Scene& scene);

struct Ray {
  render::Vec3f origin, direction;  // direction: unit length
};

// The ray from the eye through the window point (x, y) in pixels from the top left.
Ray rayThroughPixel(const render::OrbitCamera& camera, double x, double y, int width, int height);

// Where the ray meets the plane through `point` facing the camera; none when it runs parallel
// or away. Dragging moves the probe in that plane, so it follows the cursor at its depth.
std::optional<render::Vec3f> dragTarget(const render::OrbitCamera& camera, const Ray& ray,
                                        const render::Vec3f& point);

// What a click grabs: the particle nearest the eye within `reach` of the ray, of an object that
// `grabbable` allows (by object index; `object` gives each particle's, -1 for none, and
// `position` x, y, z per particle). Its object, and how far along the ray it lies.
struct Pick {
  std::size_t object = 0;
  float distance = 0.0f;
};
std::optional<Pick> pickObject(const Ray& ray, const std::vector<float>& position,
                               const std::vector<std::int32_t>& object,
                               const std::vector<bool>& grabbable, float reach);

}  // namespace sph::view
