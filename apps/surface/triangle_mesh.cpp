#include "triangle_mesh.hpp"

#include <algorithm>
#include <utility>

namespace sph::surface {

MeshCheck checkMesh(const TriangleMesh& mesh) {
  MeshCheck check;
  // Each directed edge once per triangle; an edge of a closed, oriented manifold appears once
  // in each direction.
  std::vector<std::pair<std::uint64_t, int>> edges;  // undirected key, +1 or -1 by direction
  edges.reserve(mesh.triangles.size());
  const auto& t = mesh.triangles;
  const auto& v = mesh.vertices;
  for (std::size_t k = 0; k + 2 < t.size(); k += 3) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = t[k + std::size_t(e)], b = t[k + std::size_t((e + 1) % 3)];
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      edges.push_back({key, a < b ? 1 : -1});
    }
    const float* p = &v[3 * std::size_t(t[k])];
    const float* q = &v[3 * std::size_t(t[k + 1])];
    const float* r = &v[3 * std::size_t(t[k + 2])];
    // p · (q × r) / 6: the signed volume of the tetrahedron on the origin.
    const double cross[3] = {double(q[1]) * r[2] - double(q[2]) * r[1],
                             double(q[2]) * r[0] - double(q[0]) * r[2],
                             double(q[0]) * r[1] - double(q[1]) * r[0]};
    check.volume += (p[0] * cross[0] + p[1] * cross[1] + p[2] * cross[2]) / 6.0;
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    int direction = 0;
    while (j < edges.size() && edges[j].first == edges[i].first) direction += edges[j++].second;
    const std::size_t uses = j - i;
    if (uses == 1)
      ++check.openEdges;
    else if (uses > 2)
      ++check.overusedEdges;
    else if (direction != 0)
      ++check.misorientedEdges;
    i = j;
  }
  return check;
}

}  // namespace sph::surface
