// The built-in objects' drawn surfaces in particle ids, and their placing at a frame.
#include <algorithm>

#include "sim/simulation_impl.hpp"
#include "sph/object_surface.hpp"
#include "sph/simulation.hpp"

namespace sph {

std::vector<ObjectSurfaceMesh> Simulation::objectSurfaces() const {
  const Impl& s = *impl_;
  std::vector<ObjectSurfaceMesh> out;
  if (!s.coupling.objects) return out;
  s.coupling.objects->wait();
  const objects::ObjectWorld& world = s.coupling.objects->world();
  // Object particle ids follow the walls' (simulation_output.cpp).
  const std::uint64_t firstId = s.counts.initialFluid + s.engine->wallCount();
  for (std::size_t o = 0; o < world.objectCount(); ++o) {
    const objects::DrawnSurface& drawn = world.drawnSurface(o);
    if (drawn.triangles.empty()) continue;
    ObjectSurfaceMesh mesh;
    mesh.object = std::int32_t(o);
    for (std::size_t v = 0; v < drawn.vertex.size(); ++v) {
      const objects::DVec3 x = drawn.vertex[v], abh = drawn.coordinate[v];
      mesh.restPosition.insert(mesh.restPosition.end(), {float(x.x), float(x.y), float(x.z)});
      mesh.coordinate.insert(mesh.coordinate.end(), {float(abh.x), float(abh.y), float(abh.z)});
      for (std::uint32_t k : drawn.anchor[v]) mesh.anchor.push_back(std::uint32_t(firstId + k));
    }
    for (const auto& t : drawn.triangles)
      mesh.triangles.insert(mesh.triangles.end(), t.begin(), t.end());
    out.push_back(std::move(mesh));
  }
  return out;
}

PlacedSurface placeObjectSurface(const ObjectSurfaceMesh& mesh, const ParticleFrame& frame) {
  const std::size_t vertices = mesh.vertexCount();
  PlacedSurface out;
  out.position = mesh.restPosition;
  out.open.assign(mesh.triangleCount(), 0);
  // The row of each anchor, or none when the frame lacks it: the frame's order is not relied on
  // (a renderer appends the walls behind the objects).
  constexpr std::size_t kMissing = ~std::size_t(0);
  std::vector<std::size_t> rows;
  std::uint32_t lowest = 0;
  if (!mesh.anchor.empty()) {
    const auto [lo, hi] = std::minmax_element(mesh.anchor.begin(), mesh.anchor.end());
    lowest = *lo;
    rows.assign(std::size_t(*hi - *lo) + 1, kMissing);
    for (std::size_t i = 0; i < frame.size(); ++i)
      if (frame.id[i] >= *lo && frame.id[i] <= *hi) rows[frame.id[i] - *lo] = i;
  }
  const auto rowOf = [&](std::uint32_t id) { return rows[id - lowest]; };
  std::vector<std::uint8_t> missing(vertices, 0), torn(vertices, 0);
  const bool hasTears = frame.torn.size() == frame.size();
  for (std::size_t v = 0; v < vertices; ++v) {
    std::size_t row[3];
    for (int a = 0; a < 3; ++a) row[a] = rowOf(mesh.anchor[3 * v + a]);
    if (row[0] == kMissing || row[1] == kMissing || row[2] == kMissing) {
      missing[v] = 1;
      continue;
    }
    anchoredPoint(&frame.position[3 * row[0]], &frame.position[3 * row[1]],
                  &frame.position[3 * row[2]], &mesh.coordinate[3 * v], &out.position[3 * v]);
    torn[v] = hasTears && frame.torn[row[0]] != 0;
  }
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t* v = &mesh.triangles[3 * t];
    const bool anyMissing = missing[v[0]] || missing[v[1]] || missing[v[2]];
    out.open[t] = anyMissing || (torn[v[0]] && torn[v[1]] && torn[v[2]]);
  }
  return out;
}

}  // namespace sph
