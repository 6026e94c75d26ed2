#include "objects/shape_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "sph/core/constants.hpp"
#include "sph/error.hpp"

namespace sph::objects {

namespace {

std::string describe(const Vec3d& v) {
  return "[" + formatNumber(v[0]) + ", " + formatNumber(v[1]) + ", " + formatNumber(v[2]) + "]";
}

[[noreturn]] void fail(const std::string& where, const std::string& key, const std::string& what) {
  throw InputError(where + "." + key + ": " + what);
}

void requirePositive(double value, const std::string& where, const std::string& key) {
  if (!(value > 0.0) || !std::isfinite(value))
    fail(where, key, "expected a positive number, got " + formatNumber(value));
}

int roundCount(double v) {
  return int(std::lround(v));
}

struct Sink {
  ShapeSamples& out;
  void add(DVec3 p, DVec3 n, bool surface) {
    out.position.push_back(p);
    out.normal.push_back(normalized(n));
    out.surface.push_back(surface ? 1 : 0);
  }
};

// Box: the points of the lattice with n_a = round(2 e_a / s) intervals per axis (spacing
// 2 e_a / n_a ≈ s, outer layer on the faces) whose depth — lattice steps to the nearest face —
// is below `layers` (all of them when solid). Normals point out of the nearest faces.
void sampleBox(const ShapeDesc& shape, double s, int layers, Sink& sink) {
  const DVec3 c = toD(shape.center);
  const double e[3] = {shape.halfExtents[0], shape.halfExtents[1], shape.halfExtents[2]};
  int n[3];
  for (int a = 0; a < 3; ++a) n[a] = std::max(1, roundCount(2.0 * e[a] / s));
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i) {
        const int idx[3] = {i, j, k};
        int depthAxis[3], depth = 1 << 30;
        for (int a = 0; a < 3; ++a) {
          depthAxis[a] = std::min(idx[a], n[a] - idx[a]);
          depth = std::min(depth, depthAxis[a]);
        }
        if (!shape.solid && depth >= layers) continue;
        double p[3], normal[3] = {0, 0, 0};
        for (int a = 0; a < 3; ++a) {
          p[a] = -e[a] + 2.0 * e[a] * idx[a] / n[a];
          if (depthAxis[a] == depth && 2 * idx[a] != n[a]) normal[a] = 2 * idx[a] < n[a] ? -1 : 1;
        }
        DVec3 nrm{normal[0], normal[1], normal[2]};
        if (dot(nrm, nrm) == 0.0) nrm = {0, 0, 1};  // the centre of a solid box
        sink.add(c + DVec3{p[0], p[1], p[2]}, nrm, depth == 0);
      }
}

// Sphere: Fibonacci shells (González 2010), ≈ 4π r²/s² points each, at r − k s; a single centre
// particle once a shell would be smaller than s/2.
void sampleSphere(const ShapeDesc& shape, double s, int layers, Sink& sink) {
  const DVec3 c = toD(shape.center);
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int k = 0; shape.solid || k < layers; ++k) {
    const double r = shape.radius - k * s;
    if (r < 0.5 * s) {
      sink.add(c, {0, 0, 1}, k == 0);
      break;
    }
    const int count = std::max(1, roundCount(4.0 * kPi * r * r / (s * s)));
    for (int i = 0; i < count; ++i) {
      const double z = 1.0 - (2.0 * i + 1.0) / count;
      const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = golden * i;
      const DVec3 u{rho * std::cos(phi), rho * std::sin(phi), z};
      sink.add(c + u * r, u, k == 0);
    }
  }
}

// A ring of `count` points of radius r about the axis at axial position t; `phase` in units of
// the angular step staggers successive rings so that the holes between them are triangles.
// Normal: radialWeight × the radial direction + axialNormal.
void addRing(Sink& sink, DVec3 c, DVec3 axis, DVec3 u, DVec3 v, double t, double r, int count,
             double phase, double radialWeight, DVec3 axialNormal, bool surface) {
  for (int i = 0; i < count; ++i) {
    const double angle = 2.0 * kPi * (i + phase) / count;
    const DVec3 radial = u * std::cos(angle) + v * std::sin(angle);
    sink.add(c + axis * t + radial * r, radial * radialWeight + axialNormal, surface);
  }
}

int ringCount(double r, double s) {
  return std::max(3, roundCount(2.0 * kPi * r / s));
}

// Points along the axis from −h to h, the core of solid round shapes (deep inside, so any unit
// normal serves).
void addAxisLine(Sink& sink, DVec3 c, DVec3 axis, double h, double s) {
  const int n = roundCount(2.0 * h / s);
  if (n == 0) {
    sink.add(c, axis, false);
    return;
  }
  for (int j = 0; j <= n; ++j) sink.add(c + axis * (-h + 2.0 * h * j / n), axis, false);
}

// Capsule: per layer of radius r_k = r − k s, rings along the segment (round(length/s) + 1)
// and hemispherical caps of latitude rings ending in a pole point.
void sampleCapsule(const ShapeDesc& shape, double s, int layers, Sink& sink) {
  const DVec3 c = toD(shape.center), axis = normalized(toD(shape.axis));
  DVec3 u, v;
  perpendicularFrame(axis, u, v);
  const double h = 0.5 * shape.length;
  for (int k = 0; shape.solid || k < layers; ++k) {
    const double r = shape.radius - k * s;
    if (k > 0 && r < 0.5 * s) {
      addAxisLine(sink, c, axis, h, s);
      break;
    }
    const int rings = h > 0.0 ? roundCount(2.0 * h / s) + 1 : 1;
    for (int j = 0; j < rings; ++j) {
      const double t = rings > 1 ? -h + 2.0 * h * j / (rings - 1) : 0.0;
      addRing(sink, c, axis, u, v, t, r, ringCount(r, s), 0.5 * (j % 2), 1.0, {0, 0, 0}, k == 0);
    }
    const int latitudes = std::max(1, roundCount(0.5 * kPi * r / s));
    for (int end = -1; end <= 1; end += 2) {
      for (int j = 1; j < latitudes; ++j) {
        const double theta = 0.5 * kPi * j / latitudes;
        const double rho = r * std::cos(theta);
        const int count = std::max(3, roundCount(2.0 * kPi * rho / s));
        const DVec3 along = axis * (end * std::sin(theta));
        // Radial part cos θ, axial part sin θ: the sphere's normal.
        for (int i = 0; i < count; ++i) {
          const double angle = 2.0 * kPi * (i + 0.5 * ((rings + j) % 2)) / count;
          const DVec3 radial = u * std::cos(angle) + v * std::sin(angle);
          const DVec3 n = radial * std::cos(theta) + along;
          sink.add(c + axis * (end * h) + n * r, n, k == 0);
        }
      }
      sink.add(c + axis * (end * (h + r)), axis * end, k == 0);
    }
  }
}

// Tube: per layer of radius R_k = R − k s, rings of round(2π R_k / s) points, round(L_k / s) + 1
// of them along the axis; when capped, each layer is closed by flat discs of concentric rings
// (R_k / round(R_k / s) apart) and a centre point, and inner layers are shorter by s per end.
// Solid: every layer spans the full length, down to a line of points on the axis.
void sampleTube(const ShapeDesc& shape, double s, int layers, Sink& sink) {
  const DVec3 c = toD(shape.center), axis = normalized(toD(shape.axis));
  DVec3 u, v;
  perpendicularFrame(axis, u, v);
  const bool closedLayers = shape.capped && !shape.solid;
  for (int k = 0; shape.solid || k < layers; ++k) {
    const double r = shape.radius - k * s;
    const double h = 0.5 * shape.length - (closedLayers ? k * s : 0.0);
    if (h < 0.0) break;
    if (k > 0 && r < 0.5 * s) {
      if (shape.solid) addAxisLine(sink, c, axis, h, s);
      break;
    }
    const int rings = roundCount(2.0 * h / s) + 1;
    const int around = ringCount(r, s);
    // The outer layer's rings, in order over the surface: the wall's, then each disc's.
    std::vector<SampleRing> wall, discs[2];
    const auto record = [&](std::vector<SampleRing>& to, int count, double phase) {
      if (k == 0 && !shape.solid) to.push_back({sink.out.position.size(), count, phase});
    };
    for (int j = 0; j < rings; ++j) {
      const double t = rings > 1 ? -h + 2.0 * h * j / (rings - 1) : 0.0;
      const bool end = j == 0 || j == rings - 1;
      DVec3 axial{0, 0, 0};
      if (closedLayers && end) axial = axis * (j == 0 ? -1.0 : 1.0);
      record(wall, around, 0.5 * (j % 2));
      addRing(sink, c, axis, u, v, t, r, around, 0.5 * (j % 2), 1.0, axial,
              k == 0 || (shape.solid && end));
    }
    if (closedLayers) {
      const int discRings = std::max(1, roundCount(r / s));
      for (int end = -1; end <= 1; end += 2) {
        const double t = end * h;
        const DVec3 n = axis * end;
        for (int j = 1; j < discRings; ++j) {
          const double rho = r * (1.0 - double(j) / discRings);
          record(discs[(end + 1) / 2], ringCount(rho, s), 0.5 * (j % 2));
          addRing(sink, c, axis, u, v, t, rho, ringCount(rho, s), 0.5 * (j % 2), 0.0, n, k == 0);
        }
        record(discs[(end + 1) / 2], 1, 0.0);
        sink.add(c + axis * t, n, k == 0);
      }
    }
    if (k != 0 || shape.solid) continue;
    // Centre of the first disc outwards, the wall, then the second disc inwards.
    std::vector<SampleRing>& rings0 = sink.out.outerRings;
    rings0.assign(discs[0].rbegin(), discs[0].rend());
    rings0.insert(rings0.end(), wall.begin(), wall.end());
    rings0.insert(rings0.end(), discs[1].begin(), discs[1].end());
  }
}

std::filesystem::path resolveMesh(const ShapeDesc& shape, const std::string& sceneFolder) {
  std::filesystem::path file(shape.meshFile);
  if (file.is_relative() && !sceneFolder.empty()) file = std::filesystem::path(sceneFolder) / file;
  return file;
}

// Mesh: the file's triangles scaled and moved to `center`; surface samples (repeated inwards
// along their normals for extra layers) or the solid lattice, whose particles with fewer than
// six lattice neighbours are the surface.
void sampleMeshShape(const ShapeDesc& shape, double s, int layers, double inset,
                     const std::string& where, const std::string& sceneFolder, BuiltShape& built,
                     Sink& sink) {
  if (shape.meshFile.empty()) fail(where, "shape.file", "expected a mesh file, got none");
  requirePositive(shape.scale, where, "shape.scale");
  const std::filesystem::path file = resolveMesh(shape, sceneFolder);
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error))
    fail(where, "shape.file", "no such file: " + file.string());
  built.mesh = loadMesh(file);
  const DVec3 c = toD(shape.center);
  for (Vec3& vertex : built.mesh.vertices) vertex = toF(c + toD(vertex) * shape.scale);
  const bool closed = isClosed(built.mesh);
  if (shape.solid && !closed)
    fail(where, "shape.solid", "a solid mesh must be closed (every edge shared by two triangles)");
  built.enclosesVolume = closed && !shape.solid;

  const SampledPoints points =
      shape.solid ? sampleMeshSolid(built.mesh, float(s)) : sampleMeshSurface(built.mesh, float(s));
  if (points.position.empty())
    fail(where, "shape.file", file.string() + " gives no particles at spacing " + formatNumber(s));
  if (!shape.solid) {
    for (int k = 0; k < layers; ++k)
      for (std::size_t i = 0; i < points.position.size(); ++i) {
        const DVec3 n = toD(points.normal[i]);
        sink.add(toD(points.position[i]) - n * (inset + k * s), n, k == 0);
      }
    return;
  }
  std::vector<DVec3> lattice(points.position.size());
  for (std::size_t i = 0; i < lattice.size(); ++i) lattice[i] = toD(points.position[i]);
  PointGrid grid;
  grid.build(lattice, s);
  for (std::size_t i = 0; i < lattice.size(); ++i) {
    int neighbours = 0;
    grid.forEachCandidate(lattice[i], 1.1 * s, [&](std::uint32_t j) {
      const double d = norm(lattice[j] - lattice[i]);
      if (j != i && d < 1.1 * s) ++neighbours;
    });
    sink.add(lattice[i], toD(points.normal[i]), neighbours < 6);
  }
}

void validateShape(const ShapeDesc& shape, int layers, const std::string& where) {
  if (layers < 1) fail(where, "shape.layers", "expected at least 1, got " + std::to_string(layers));
  for (double x : shape.center)
    if (!std::isfinite(x))
      fail(where, "shape.center", "expected finite numbers, got " + describe(shape.center));
  switch (shape.kind) {
    case ShapeKind::Box:
      for (int a = 0; a < 3; ++a)
        if (!(shape.halfExtents[a] > 0.0) || !std::isfinite(shape.halfExtents[a]))
          fail(where, "shape.half_extents",
               "expected three positive numbers, got " + describe(shape.halfExtents));
      break;
    case ShapeKind::Sphere:
      requirePositive(shape.radius, where, "shape.radius");
      break;
    case ShapeKind::Capsule:
    case ShapeKind::Tube:
      requirePositive(shape.radius, where, "shape.radius");
      if (shape.kind == ShapeKind::Tube) {
        requirePositive(shape.length, where, "shape.length");
      } else if (!(shape.length >= 0.0) || !std::isfinite(shape.length)) {
        fail(where, "shape.length", "expected a number ≥ 0, got " + formatNumber(shape.length));
      }
      if (!(norm(toD(shape.axis)) > 0.0) || !std::isfinite(norm(toD(shape.axis))))
        fail(where, "shape.axis", "expected a non-zero direction, got " + describe(shape.axis));
      break;
    case ShapeKind::Mesh:
      break;
  }
}

double distanceToSegment(DVec3 p, DVec3 c, DVec3 axis, double h, double* axial) {
  const double t = dot(p - c, axis);
  if (axial) *axial = t;
  const double clamped = std::clamp(t, -h, h);
  return norm(p - (c + axis * clamped));
}

}  // namespace

ShapeDesc insetShape(const ShapeDesc& shape, double inset, const std::string& where) {
  ShapeDesc placed = shape;
  if (!(inset > 0.0)) return placed;
  const std::string why = "a solid body's particles lie half a spacing (" + formatNumber(inset) +
                          " m) inside its surface; expected ";
  switch (shape.kind) {
    case ShapeKind::Box:
      for (int a = 0; a < 3; ++a) {
        if (!(shape.halfExtents[a] > inset))
          fail(where, "shape.half_extents",
               why + "each above " + formatNumber(inset) + ", got " + describe(shape.halfExtents));
        placed.halfExtents[a] -= inset;
      }
      break;
    case ShapeKind::Sphere:
    case ShapeKind::Capsule:
      if (!(shape.radius > inset))
        fail(where, "shape.radius",
             why + "more than " + formatNumber(inset) + ", got " + formatNumber(shape.radius));
      placed.radius -= inset;
      break;
    case ShapeKind::Tube:  // described by its particle layer
    case ShapeKind::Mesh:  // moved along its normals as it is sampled
      break;
  }
  return placed;
}

ShapeSamples sampleShape(const ShapeDesc& described, double spacing, double inset,
                         const std::string& where, const std::string& sceneFolder,
                         BuiltShape& built) {
  const int layers = described.layers;
  validateShape(described, layers, where);
  const ShapeDesc shape = insetShape(described, inset, where);
  built.desc = shape;
  built.spacing = spacing;
  ShapeSamples samples;
  Sink sink{samples};
  switch (shape.kind) {
    case ShapeKind::Box:
      sampleBox(shape, spacing, layers, sink);
      built.enclosesVolume = !shape.solid;
      break;
    case ShapeKind::Sphere:
      sampleSphere(shape, spacing, layers, sink);
      built.enclosesVolume = !shape.solid;
      break;
    case ShapeKind::Capsule:
      sampleCapsule(shape, spacing, layers, sink);
      built.enclosesVolume = !shape.solid;
      break;
    case ShapeKind::Tube:
      if (roundCount(2.0 * kPi * shape.radius / spacing) < 3)
        fail(where, "shape.radius",
             "a tube needs at least 3 particles around (2π radius / spacing ≥ 2.5), got radius " +
                 formatNumber(shape.radius) + " at spacing " + formatNumber(spacing));
      sampleTube(shape, spacing, layers, sink);
      built.enclosesVolume = shape.capped && !shape.solid;
      break;
    case ShapeKind::Mesh:
      sampleMeshShape(shape, spacing, layers, inset, where, sceneFolder, built, sink);
      built.particles = samples.position;
      built.particleGrid.build(built.particles, spacing);
      break;
  }
  return samples;
}

bool BuiltShape::interiorContains(DVec3 p, double margin) const {
  if (!enclosesVolume) return false;
  // The cavity ends at the innermost particle layer.
  const double inner = (desc.layers - 1) * spacing;
  const DVec3 c = toD(desc.center);
  switch (desc.kind) {
    case ShapeKind::Box: {
      const double d[3] = {p.x - c.x, p.y - c.y, p.z - c.z};
      for (int a = 0; a < 3; ++a) {
        const double e = desc.halfExtents[a];
        const int n = std::max(1, roundCount(2.0 * e / spacing));
        const double innerHalf = e - (desc.layers - 1) * (2.0 * e / n);
        if (!(std::abs(d[a]) < innerHalf - margin)) return false;
      }
      return true;
    }
    case ShapeKind::Sphere:
      return norm(p - c) < desc.radius - inner - margin;
    case ShapeKind::Capsule:
      return distanceToSegment(p, c, normalized(toD(desc.axis)), 0.5 * desc.length, nullptr) <
             desc.radius - inner - margin;
    case ShapeKind::Tube: {
      const DVec3 axis = normalized(toD(desc.axis));
      double axial = 0.0;
      distanceToSegment(p, c, axis, 0.5 * desc.length, &axial);
      const double radial = norm((p - c) - axis * axial);
      return radial < desc.radius - inner - margin &&
             std::abs(axial) < 0.5 * desc.length - inner - margin;
    }
    case ShapeKind::Mesh: {
      if (!meshContains(mesh, toF(p))) return false;
      bool clear = true;
      particleGrid.forEachCandidate(p, margin, [&](std::uint32_t i) {
        if (norm(particles[i] - p) < margin) clear = false;
      });
      return clear;
    }
  }
  return false;
}

}  // namespace sph::objects
