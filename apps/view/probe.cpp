#include "probe.hpp"

#include <cmath>

namespace sph::view {

using render::Vec3f;

Vec3d addProbe(Scene& scene) {
  const AxisBox& domain = scene.domain.box;
  const double radius = 3.0 * scene.fluid.spacing;
  const Vec3d centre{0.5 * (domain.min[0] + domain.max[0]), domain.max[1] + 2.0 * radius,
                     0.5 * (domain.min[2] + domain.max[2])};
  ObjectDesc probe;
  probe.name = kProbeName;
  probe.motion = ObjectMotion::Kinematic;
  probe.shape.kind = ShapeKind::Sphere;
  probe.shape.center = centre;
  probe.shape.radius = radius;
  scene.objects.push_back(probe);
  return centre;
}

Ray rayThroughPixel(const render::OrbitCamera& camera, double x, double y, int width, int height) {
  const Vec3f eye = camera.eye();
  const Vec3f forward = render::normalize(render::subtract(camera.target, eye));
  const Vec3f right = render::normalize(render::cross(forward, Vec3f{0, 1, 0}));
  const Vec3f up = render::cross(right, forward);
  const float aspect = float(width) / float(height > 0 ? height : 1);
  const float tanHalf = std::tan(0.5f * camera.verticalFov);
  const float ndcX = float(2.0 * x / width - 1.0);
  const float ndcY = float(1.0 - 2.0 * y / height);
  const Vec3f direction = render::normalize(
      render::add(forward, render::add(render::scale(right, ndcX * tanHalf * aspect),
                                       render::scale(up, ndcY * tanHalf))));
  return {eye, direction};
}

std::optional<render::Vec3f> dragTarget(const render::OrbitCamera& camera, const Ray& ray,
                                        const render::Vec3f& point) {
  const Vec3f normal = render::normalize(render::subtract(camera.target, camera.eye()));
  const float facing = render::dot(ray.direction, normal);
  if (std::abs(facing) < 1e-6f) return std::nullopt;
  const float t = render::dot(render::subtract(point, ray.origin), normal) / facing;
  if (!(t > 0.0f)) return std::nullopt;
  return render::add(ray.origin, render::scale(ray.direction, t));
}

std::optional<Pick> pickObject(const Ray& ray, const std::vector<float>& position,
                               const std::vector<std::int32_t>& object,
                               const std::vector<bool>& grabbable, float reach) {
  std::optional<Pick> best;
  for (std::size_t i = 0; i < object.size(); ++i) {
    const std::int32_t o = object[i];
    if (o < 0 || std::size_t(o) >= grabbable.size() || !grabbable[std::size_t(o)]) continue;
    const Vec3f p{position[3 * i], position[3 * i + 1], position[3 * i + 2]};
    const Vec3f fromEye = render::subtract(p, ray.origin);
    const float along = render::dot(fromEye, ray.direction);
    if (!(along > 0.0f)) continue;  // behind the eye
    const Vec3f across = render::subtract(fromEye, render::scale(ray.direction, along));
    if (render::dot(across, across) > reach * reach) continue;
    if (!best || along < best->distance) best = Pick{std::size_t(o), along};
  }
  return best;
}

}  // namespace sph::view
