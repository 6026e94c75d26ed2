// An object world's particles as a frame and its drawn surfaces as ObjectSurfaceMeshes, with
// particle indices for ids: what the drawn-surface and render tests place and draw.
#pragma once

#include <vector>

#include "objects/object_world.hpp"
#include "sph/frame.hpp"
#include "sph/object_surface.hpp"

namespace sph::objects::test {

inline ParticleFrame frameOf(const ParticleState& p) {
  ParticleFrame f;
  for (std::size_t k = 0; k < p.size(); ++k) {
    f.id.push_back(std::uint32_t(k));
    f.position.insert(f.position.end(), {p.position[k].x, p.position[k].y, p.position[k].z});
    f.velocity.insert(f.velocity.end(), {0.0f, 0.0f, 0.0f});
    f.density.push_back(1000.0f);
    f.pressure.push_back(0.0f);
    f.kind.push_back(static_cast<std::uint8_t>(ParticleKind::Object));
    f.object.push_back(p.object[k]);
    f.surface.push_back(p.surface[k]);
    f.torn.push_back(p.cut[k]);
  }
  return f;
}

inline ObjectSurfaceMesh meshOf(const DrawnSurface& d, std::int32_t object = 0) {
  ObjectSurfaceMesh m;
  m.object = object;
  for (std::size_t v = 0; v < d.vertex.size(); ++v) {
    m.restPosition.insert(m.restPosition.end(),
                          {float(d.vertex[v].x), float(d.vertex[v].y), float(d.vertex[v].z)});
    m.coordinate.insert(m.coordinate.end(), {float(d.coordinate[v].x), float(d.coordinate[v].y),
                                             float(d.coordinate[v].z)});
    m.anchor.insert(m.anchor.end(), d.anchor[v].begin(), d.anchor[v].end());
  }
  for (const auto& t : d.triangles) m.triangles.insert(m.triangles.end(), t.begin(), t.end());
  return m;
}

}  // namespace sph::objects::test
