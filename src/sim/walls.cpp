#include "sim/walls.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <system_error>

#include "objects/math3d.hpp"
#include "objects/mesh.hpp"
#include "objects/point_grid.hpp"
#include "objects/shape_sampling.hpp"
#include "sim/sampling.hpp"
#include "sph/core/periodic.hpp"
#include "sph/error.hpp"

namespace sph::sim {

using objects::DVec3;
using objects::toD;
using objects::toF;

// Per wall, whether a point lies where no fluid may start; empty when only the distance to the
// wall's particles decides.
struct Walls::Solids {
  std::vector<std::function<bool(DVec3)>> tests;
  objects::PointGrid grid;
  std::vector<DVec3> particles;
  double clearance = 0.0;
};

namespace {

struct Sampled {
  std::vector<DVec3> points;
  std::function<bool(DVec3)> solid;
};

struct WallContext {
  const Scene& scene;
  std::string where;  // "scene.json: walls[2]"
  double spacing;

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(where + "." + key + ": " + what);
  }
};

std::vector<DVec3> toDouble(const std::vector<Vec3>& points) {
  std::vector<DVec3> out(points.size());
  std::transform(points.begin(), points.end(), out.begin(), [](Vec3 p) { return toD(p); });
  return out;
}

bool insideBox(DVec3 p, const AxisBox& box) {
  return p.x > box.min[0] && p.x < box.max[0] && p.y > box.min[1] && p.y < box.max[1] &&
         p.z > box.min[2] && p.z < box.max[2];
}

// The object engine's shape sampler lays the layers inwards from the shape's outer surface,
// the first `inset` inside it.
std::vector<DVec3> sampleInwards(const WallContext& c, const ShapeDesc& shape, double inset) {
  objects::BuiltShape built;
  return objects::sampleShape(shape, c.spacing, inset, c.where, "", built).position;
}

Sampled sampleBox(const WallContext& c, const WallDesc& w) {
  const AxisBox box = w.box;
  if (w.fluid == FluidSide::Inside) {
    return {toDouble(sampleTank(box, w.layers, /*closed=*/true, c.spacing, c.scene.gravity)),
            [box](DVec3 p) { return !insideBox(p, box); }};
  }
  ShapeDesc shape;
  shape.kind = ShapeKind::Box;
  shape.layers = w.layers;
  for (int a = 0; a < 3; ++a) {
    shape.center[a] = 0.5 * (box.min[a] + box.max[a]);
    shape.halfExtents[a] = 0.5 * (box.max[a] - box.min[a]);
  }
  return {sampleInwards(c, shape, 0.5 * c.spacing), [box](DVec3 p) { return insideBox(p, box); }};
}

// Fluid inside: the outermost layer's radius is chosen so that the innermost lies half a
// spacing outside the surface.
Sampled sampleSphere(const WallContext& c, const WallDesc& w) {
  const double d = c.spacing;
  const bool inside = w.fluid == FluidSide::Inside;
  ShapeDesc shape;
  shape.kind = ShapeKind::Sphere;
  shape.center = w.center;
  shape.layers = w.layers;
  shape.radius = inside ? w.radius + (w.layers - 0.5) * d : w.radius;
  const DVec3 centre = toD(w.center);
  const double r = w.radius;
  return {sampleInwards(c, shape, inside ? 0.0 : 0.5 * d),
          [=](DVec3 p) { return (norm(p - centre) < r) != inside; }};
}

Sampled sampleCylinder(const WallContext& c, const WallDesc& w) {
  const double d = c.spacing;
  const bool inside = w.fluid == FluidSide::Inside;
  ShapeDesc shape;
  shape.kind = ShapeKind::Tube;  // described by its outermost particle layer
  shape.center = w.center;
  shape.axis = w.axis;
  shape.capped = w.capped;
  shape.layers = w.layers;
  const double outer = inside ? (w.layers - 0.5) * d : -0.5 * d;
  shape.radius = w.radius + outer;
  shape.length = w.capped ? w.length + 2.0 * outer : w.length;
  const DVec3 centre = toD(w.center), axis = objects::normalized(toD(w.axis));
  const double r = w.radius, half = 0.5 * w.length;
  const double band = r + (w.layers + 0.5) * d;
  const bool capped = w.capped;
  return {sampleInwards(c, shape, 0.0), [=](DVec3 p) {
            const double t = dot(p - centre, axis);
            const double radial = norm(p - centre - axis * t);
            const bool within = radial < r && std::abs(t) < half;
            if (!inside) return within;
            // An open pipe's ends let the fluid out: only its wall is solid.
            return capped ? !within : radial > r && radial < band && std::abs(t) < half;
          }};
}

// The parallelogram on a lattice of about one spacing, its layers behind it.
Sampled samplePlane(const WallContext& c, const WallDesc& w) {
  const double d = c.spacing;
  const DVec3 corner = toD(w.corner), e1 = toD(w.edge1), e2 = toD(w.edge2);
  const DVec3 n = objects::normalized(cross(e1, e2));
  const int n1 = std::max(1, int(std::lround(norm(e1) / d)));
  const int n2 = std::max(1, int(std::lround(norm(e2) / d)));
  Sampled out;
  for (int k = 0; k < w.layers; ++k)
    for (int j = 0; j < n2; ++j)
      for (int i = 0; i < n1; ++i)
        out.points.push_back(corner + e1 * ((i + 0.5) / n1) + e2 * ((j + 0.5) / n2) -
                             n * ((k + 0.5) * d));
  // A ramp is the face of what lies behind it, down to the floor it stands on: solid is the
  // prism behind the parallelogram. The coordinates (a, b) along the edges solve the 2×2
  // system of their Gram matrix.
  const double g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2);
  const double det = g11 * g22 - g12 * g12;
  out.solid = [=](DVec3 p) {
    const DVec3 r = p - corner;
    if (!(dot(r, n) < 0.0)) return false;
    const double r1 = dot(r, e1), r2 = dot(r, e2);  // the edges lie in the plane
    const double a = (g22 * r1 - g12 * r2) / det, b = (g11 * r2 - g12 * r1) / det;
    return a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0;
  };
  return out;
}

Sampled sampleMesh(const WallContext& c, const WallDesc& w) {
  std::filesystem::path file(w.meshFile);
  const std::filesystem::path folder = std::filesystem::path(c.scene.sourcePath).parent_path();
  if (file.is_relative() && !folder.empty()) file = folder / file;
  std::error_code error;
  if (w.meshFile.empty()) c.fail("file", "expected a mesh file (OBJ or STL), got none");
  if (!std::filesystem::is_regular_file(file, error))
    c.fail("file", "no such file: " + file.string());
  objects::TriangleMesh mesh;
  try {
    mesh = objects::loadMesh(file);
  } catch (const InputError& e) {
    c.fail("file", e.what());
  }
  if (mesh.triangles.empty()) c.fail("file", file.string() + " holds no triangles");
  const DVec3 centre = toD(w.center);
  for (Vec3& vertex : mesh.vertices) vertex = toF(centre + toD(vertex) * w.scale);
  const bool closed = objects::isClosed(mesh);
  if (!closed && !w.open)
    c.fail("file", file.string() +
                       " is not closed (an edge is not shared by exactly two triangles), so fluid "
                       "would leak through its holes; set open: true if they are meant");
  // Each layer is the surface moved back, sampled on its own: a layer made by moving the
  // surface's samples along their normals would open gaps at the edges, where the samples
  // there follow one face only.
  Sampled out;
  for (int k = 0; k < w.layers; ++k) {
    const objects::TriangleMesh layer = objects::offsetAlongNormals(mesh, -(k + 0.5) * c.spacing);
    const objects::SampledPoints samples = objects::sampleMeshSurface(layer, float(c.spacing));
    for (const Vec3& p : samples.position) out.points.push_back(toD(p));
  }
  if (out.points.empty())
    c.fail("file", file.string() + " gives no particles at spacing " + formatNumber(c.spacing));
  if (closed) {
    // Normals out of the enclosed volume put the fluid outside it, and the inside is solid.
    const bool fluidOutside = objects::signedVolume(mesh) > 0.0;
    out.solid = [mesh = std::move(mesh), fluidOutside](DVec3 p) {
      return objects::meshContains(mesh, toF(p)) == fluidOutside;
    };
  }
  return out;
}

Sampled sampleWall(const WallContext& c, const WallDesc& w) {
  switch (w.kind) {
    case WallKind::Tank:
      return {toDouble(sampleTank(w.box, w.layers, w.closed, c.spacing, c.scene.gravity)), {}};
    case WallKind::Box:
      return sampleBox(c, w);
    case WallKind::Sphere:
      return sampleSphere(c, w);
    case WallKind::Cylinder:
      return sampleCylinder(c, w);
    case WallKind::Plane:
      return samplePlane(c, w);
    case WallKind::Mesh:
      return sampleMesh(c, w);
  }
  return {};
}

// The wall particles a fluid particle near a periodic face needs from beyond the other face:
// each particle within the kernel's reach of a periodic face, shifted by the period (and at a
// corner of two periodic axes, by both). Walls do not move, so these copies stay exact, and
// the fluid's passes find them as plain neighbours without wrapping.
std::vector<DVec3> periodicImages(const std::vector<DVec3>& particles, const Scene& scene,
                                  double reach) {
  const DomainDesc& d = scene.domain;
  std::vector<DVec3> images;
  for (const DVec3& p : particles) {
    const double at[3] = {p.x, p.y, p.z};
    forEachPeriodicImage(d.periodic.data(), at, d.box.min.data(), d.box.max.data(), reach,
                         [&](const int s[3]) {
                           if (s[0] == 0 && s[1] == 0 && s[2] == 0) return;
                           DVec3 q = p;
                           q.x += s[0] * (d.box.max[0] - d.box.min[0]);
                           q.y += s[1] * (d.box.max[1] - d.box.min[1]);
                           q.z += s[2] * (d.box.max[2] - d.box.min[2]);
                           images.push_back(q);
                         });
  }
  return images;
}

}  // namespace

Walls::Walls(const Scene& scene) : solids_(std::make_unique<Solids>()) {
  const double spacing = scene.fluid.spacing;
  for (std::size_t i = 0; i < scene.walls.size(); ++i) {
    const WallContext context{scene, scene.sourcePath + ": walls[" + std::to_string(i) + "]",
                              spacing};
    Sampled wall = sampleWall(context, scene.walls[i]);
    firstParticle_.push_back(solids_->particles.size());
    solids_->particles.insert(solids_->particles.end(), wall.points.begin(), wall.points.end());
    if (wall.solid) solids_->tests.push_back(std::move(wall.solid));
  }
  firstParticle_.push_back(solids_->particles.size());
  const std::vector<DVec3> images =
      periodicImages(solids_->particles, scene, scene.fluid.supportRatio * spacing);
  particles_.reserve(solids_->particles.size() + images.size());
  for (const DVec3& p : solids_->particles) particles_.push_back(toF(p));
  for (const DVec3& p : images) particles_.push_back(toF(p));
  solids_->clearance = 0.75 * spacing;
  solids_->grid.build(solids_->particles, solids_->clearance);
}

Walls::~Walls() = default;
Walls::Walls(Walls&&) noexcept = default;
Walls& Walls::operator=(Walls&&) noexcept = default;

void Walls::removeOverlap(std::vector<Vec3>& points) const {
  const Solids& s = *solids_;
  const auto blocked = [&s](Vec3 point) {
    const DVec3 p = toD(point);
    for (const auto& solid : s.tests)
      if (solid(p)) return true;
    bool near = false;
    s.grid.forEachCandidate(p, s.clearance, [&](std::uint32_t i) {
      near = near || norm(s.particles[i] - p) < s.clearance;
    });
    return near;
  };
  points.erase(std::remove_if(points.begin(), points.end(), blocked), points.end());
}

}  // namespace sph::sim
