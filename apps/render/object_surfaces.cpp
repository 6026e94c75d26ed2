#include "object_surfaces.hpp"

#include <cmath>

#include "vec3f.hpp"

namespace sph::render {

namespace {

Vec3f at(const std::vector<float>& xyz, std::size_t v) {
  return {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
}

void appendMesh(const ObjectSurfaceMesh& mesh, const ParticleFrame& frame, SurfaceTriangles& out) {
  const PlacedSurface placed = placeObjectSurface(mesh, frame);
  const std::size_t triangles = mesh.triangleCount();
  // Face normals, area-weighted (the cross product's length), and each vertex's faces.
  std::vector<Vec3f> face(triangles);
  std::vector<std::vector<std::uint32_t>> facesAt(mesh.vertexCount());
  for (std::size_t t = 0; t < triangles; ++t) {
    if (placed.open[t]) continue;
    const std::uint32_t* v = &mesh.triangles[3 * t];
    const Vec3f a = at(placed.position, v[0]);
    face[t] = cross(subtract(at(placed.position, v[1]), a), subtract(at(placed.position, v[2]), a));
    for (int c = 0; c < 3; ++c) facesAt[v[c]].push_back(std::uint32_t(t));
  }
  const float creaseCos = std::cos(kCreaseDegrees * 3.14159265f / 180.0f);
  const Rgb colour = kindColour(ParticleKind::Object, mesh.object);
  for (std::size_t t = 0; t < triangles; ++t) {
    if (placed.open[t]) {
      ++out.open;
      continue;
    }
    const Vec3f own = normalize(face[t]);
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = mesh.triangles[3 * t + c];
      Vec3f sum{0, 0, 0};
      for (std::uint32_t f : facesAt[v])
        if (dot(normalize(face[f]), own) >= creaseCos) sum = add(sum, face[f]);
      const Vec3f normal = normalize(sum);
      const Vec3f p = at(placed.position, v);
      out.corners.insert(out.corners.end(), {p[0], p[1], p[2], normal[0], normal[1], normal[2],
                                             colour.r, colour.g, colour.b});
    }
  }
}

}  // namespace

SurfaceTriangles objectSurfaceTriangles(const std::vector<ObjectSurfaceMesh>& meshes,
                                        const ParticleFrame& frame) {
  SurfaceTriangles out;
  for (const ObjectSurfaceMesh& mesh : meshes) appendMesh(mesh, frame, out);
  return out;
}

}  // namespace sph::render
