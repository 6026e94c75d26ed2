#include "objects/drawn_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "objects/point_grid.hpp"
#include "sph/core/constants.hpp"

namespace sph::objects {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// A ring of vertices: vertex first + i at angle 2π (i + phase) / count about the shape's axis.
struct Ring {
  std::uint32_t first = 0;
  int count = 0;
  double phase = 0.0;
  std::uint32_t at(int i) const { return first + std::uint32_t(i % count); }
  double angle(int i) const { return 2.0 * kPi * (i + phase) / count; }
};

// Closes the band between two rings with triangles, walking both by angle so that each
// triangle joins the nearest points; a ring of one point (a disc's centre, a pole) gives a fan.
void zip(const Ring& a, const Ring& b, std::vector<Triangle>& out) {
  if (a.count == 1 && b.count == 1) return;
  if (a.count == 1 || b.count == 1) {
    const Ring& pole = a.count == 1 ? a : b;
    const Ring& ring = a.count == 1 ? b : a;
    for (int i = 0; i < ring.count; ++i) out.push_back({pole.first, ring.at(i), ring.at(i + 1)});
    return;
  }
  int i = 0, j = 0;
  while (i < a.count || j < b.count) {
    const bool advanceA = j == b.count || (i < a.count && a.angle(i + 1) <= b.angle(j + 1));
    if (advanceA) {
      out.push_back({a.at(i), a.at(i + 1), b.at(j)});
      ++i;
    } else {
      out.push_back({a.at(i), b.at(j + 1), b.at(j)});
      ++j;
    }
  }
}

void zipAll(const std::vector<Ring>& rings, std::vector<Triangle>& out) {
  for (std::size_t r = 1; r < rings.size(); ++r) zip(rings[r - 1], rings[r], out);
}

int countAround(double rho, double s) {
  return rho > 1e-9 * s ? std::max(3, int(std::lround(2.0 * kPi * rho / s))) : 1;
}

// A surface of revolution through the profile's (axial position, radius) points, in order; a
// radius of zero is a pole.
void revolve(const std::vector<std::array<double, 2>>& profile, DVec3 c, DVec3 axis, double s,
             DrawnSurface& out) {
  DVec3 u, v;
  perpendicularFrame(axis, u, v);
  std::vector<Ring> rings;
  for (std::size_t j = 0; j < profile.size(); ++j) {
    const auto [t, rho] = profile[j];
    Ring ring{std::uint32_t(out.vertex.size()), countAround(rho, s), 0.5 * double(j % 2)};
    for (int i = 0; i < ring.count; ++i) {
      const double angle = ring.angle(i);
      out.vertex.push_back(c + axis * t + (u * std::cos(angle) + v * std::sin(angle)) * rho);
    }
    rings.push_back(ring);
  }
  zipAll(rings, out.triangles);
}

// Points from a to b (both included) at about spacing s.
void appendSteps(std::vector<std::array<double, 2>>& profile, std::array<double, 2> a,
                 std::array<double, 2> b, double s, bool includeFirst) {
  const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
  const int n = std::max(1, int(std::lround(length / s)));
  for (int k = includeFirst ? 0 : 1; k <= n; ++k) {
    const double f = double(k) / n;
    profile.push_back({a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f});
  }
}

// A quarter circle of radius r from the pole at axial position t0 − r (side −1) or t0 + r (+1)
// to the equator at t0, or back.
void appendCap(std::vector<std::array<double, 2>>& profile, double t0, double r, int side, double s,
               bool towardsPole) {
  const int n = std::max(1, int(std::lround(0.5 * kPi * r / s)));
  for (int k = 0; k <= n; ++k) {
    const int step = towardsPole ? k : n - k;
    if (!profile.empty() && k == 0) continue;   // the equator is already there
    const double theta = 0.5 * kPi * step / n;  // 0 at the equator
    profile.push_back({t0 + side * r * std::sin(theta), r * std::cos(theta)});
  }
}

void boxSurface(const ShapeDesc& box, double s, DrawnSurface& out) {
  const DVec3 c = toD(box.center);
  int n[3];
  for (int a = 0; a < 3; ++a) n[a] = std::max(1, int(std::lround(2.0 * box.halfExtents[a] / s)));
  std::map<std::array<int, 3>, std::uint32_t> index;
  const auto vertex = [&](std::array<int, 3> lattice) {
    const auto [it, added] = index.emplace(lattice, std::uint32_t(out.vertex.size()));
    if (added) {
      double p[3];
      for (int a = 0; a < 3; ++a) p[a] = box.halfExtents[a] * (2.0 * lattice[a] / n[a] - 1.0);
      out.vertex.push_back(c + DVec3{p[0], p[1], p[2]});
    }
    return it->second;
  };
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, d = (a + 2) % 3;
    for (int side : {0, n[a]})
      for (int i = 0; i < n[b]; ++i)
        for (int j = 0; j < n[d]; ++j) {
          std::array<int, 3> p00{}, p10{}, p11{}, p01{};
          for (auto* p : {&p00, &p10, &p11, &p01}) (*p)[a] = side;
          p00[b] = i, p00[d] = j;
          p10[b] = i + 1, p10[d] = j;
          p11[b] = i + 1, p11[d] = j + 1;
          p01[b] = i, p01[d] = j + 1;
          const std::uint32_t q[4] = {vertex(p00), vertex(p10), vertex(p11), vertex(p01)};
          out.triangles.push_back({q[0], q[1], q[2]});
          out.triangles.push_back({q[0], q[2], q[3]});
        }
  }
}

// The shape's surface at about spacing s, vertices and triangles in any winding.
void tessellate(const ShapeDesc& shape, const ShapeSamples& samples, const BuiltShape& built,
                double s, DrawnSurface& out) {
  const DVec3 c = toD(shape.center);
  const DVec3 axis = normalized(toD(shape.axis));
  const double r = shape.radius, h = 0.5 * shape.length;
  std::vector<std::array<double, 2>> profile;
  switch (shape.kind) {
    case ShapeKind::Box:
      boxSurface(shape, s, out);
      return;
    case ShapeKind::Sphere:
      appendCap(profile, 0.0, r, -1, s, false);
      appendCap(profile, 0.0, r, 1, s, true);
      revolve(profile, c, DVec3{0, 0, 1}, s, out);
      return;
    case ShapeKind::Capsule:
      appendCap(profile, -h, r, -1, s, false);
      appendSteps(profile, {-h, r}, {h, r}, s, false);
      appendCap(profile, h, r, 1, s, true);
      revolve(profile, c, axis, s, out);
      return;
    case ShapeKind::Tube:
      if (!samples.outerRings.empty()) {  // over the particles themselves
        std::vector<Ring> rings;
        for (const SampleRing& ring : samples.outerRings)
          rings.push_back({std::uint32_t(ring.first), ring.count, ring.phase});
        // The wall's outer face, half a spacing out from its particles' centres, as a solid
        // body's surface lies half a spacing beyond its particles.
        for (std::size_t k = 0; k < samples.position.size(); ++k)
          out.vertex.push_back(samples.position[k] + samples.normal[k] * (0.5 * s));
        zipAll(rings, out.triangles);
        return;
      }
      if (shape.capped) appendSteps(profile, {-h, 0.0}, {-h, r}, s, true);
      appendSteps(profile, {-h, r}, {h, r}, s, !shape.capped);
      if (shape.capped) appendSteps(profile, {h, r}, {h, 0.0}, s, false);
      revolve(profile, c, axis, s, out);
      return;
    case ShapeKind::Mesh:
      for (const Vec3& p : built.mesh.vertices) out.vertex.push_back(toD(p));
      out.triangles = built.mesh.triangles;
      return;
  }
}

// Keeps only the vertices a triangle uses (a tube drawn through its outer layer leaves the
// inner layers' samples out).
void dropUnusedVertices(DrawnSurface& out) {
  std::vector<std::uint32_t> renumber(out.vertex.size(), ~0u);
  std::vector<DVec3> kept;
  for (Triangle& t : out.triangles)
    for (std::uint32_t& v : t) {
      if (renumber[v] == ~0u) {
        renumber[v] = std::uint32_t(kept.size());
        kept.push_back(out.vertex[v]);
      }
      v = renumber[v];
    }
  out.vertex = std::move(kept);
}

// Ties each vertex to the three nearest surface particles that make a well-shaped triangle.
void anchorVertices(const ShapeSamples& samples, double s, DrawnSurface& out) {
  std::vector<std::uint32_t> candidates;
  for (std::size_t k = 0; k < samples.position.size(); ++k)
    if (samples.surface[k]) candidates.push_back(std::uint32_t(k));
  if (candidates.empty())
    for (std::size_t k = 0; k < samples.position.size(); ++k)
      candidates.push_back(std::uint32_t(k));
  std::vector<DVec3> points;
  for (std::uint32_t k : candidates) points.push_back(samples.position[k]);
  PointGrid grid;
  grid.build(points, s);

  out.anchor.resize(out.vertex.size());
  out.coordinate.resize(out.vertex.size());
  std::vector<std::pair<double, std::uint32_t>> near;
  for (std::size_t v = 0; v < out.vertex.size(); ++v) {
    const DVec3 p = out.vertex[v];
    bool found = false;
    for (double radius = 2.0 * s; !found && radius < 1e3 * s; radius *= 2.0) {
      near.clear();
      grid.forEachCandidate(p, radius, [&](std::uint32_t k) {
        const double d = norm(points[k] - p);
        if (d <= radius) near.push_back({d, k});
      });
      std::sort(near.begin(), near.end());
      if (near.size() < 3) continue;
      const DVec3 x0 = points[near[0].second], x1 = points[near[1].second];
      const DVec3 e1 = x1 - x0;
      for (std::size_t m = 2; m < near.size() && !found; ++m) {
        const DVec3 e2 = points[near[m].second] - x0;
        // Sides at least ~17° apart: the normal of a thin triangle turns wildly as it deforms.
        if (norm(cross(e1, e2)) < 0.3 * norm(e1) * norm(e2)) continue;
        out.anchor[v] = {candidates[near[0].second], candidates[near[1].second],
                         candidates[near[m].second]};
        out.coordinate[v] = anchorCoordinates(x0, x1, points[near[m].second], p);
        found = true;
      }
    }
    if (!found) {  // fewer than three particles off one line: the vertex rides the nearest
      std::uint32_t k = 0;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t m = 0; m < points.size(); ++m)
        if (norm(points[m] - p) < best) best = norm(points[m] - p), k = std::uint32_t(m);
      out.anchor[v] = {candidates[k], candidates[k], candidates[k]};
      out.coordinate[v] = {0, 0, 0};
    }
  }
}

// Drops triangles of no area (a pole's zero-length edges) and winds each as the outward normals
// of the particles its vertices hang on.
void orientOutward(const ShapeSamples& samples, double s, DrawnSurface& out) {
  std::vector<Triangle> kept;
  for (Triangle t : out.triangles) {
    const DVec3 a = out.vertex[t[0]], b = out.vertex[t[1]], c = out.vertex[t[2]];
    const DVec3 n = cross(b - a, c - a);
    if (norm(n) <= 1e-9 * s * s) continue;
    DVec3 outward{0, 0, 0};
    for (std::uint32_t v : t) outward += samples.normal[out.anchor[v][0]];
    if (dot(n, outward) < 0.0) std::swap(t[1], t[2]);
    kept.push_back(t);
  }
  out.triangles = std::move(kept);
}

}  // namespace

DVec3 anchorCoordinates(DVec3 x0, DVec3 x1, DVec3 x2, DVec3 p) {
  const DVec3 e1 = x1 - x0, e2 = x2 - x0;
  const DVec3 n = normalized(cross(e1, e2));
  DVec3 d = p - x0;
  const double height = dot(d, n);
  d -= n * height;
  // The in-plane part from the 2×2 normal equations of d = α e1 + β e2.
  const double a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2);
  const double b1 = dot(d, e1), b2 = dot(d, e2);
  const double det = a11 * a22 - a12 * a12;
  if (!(det > 0.0)) return {0, 0, height};
  return {(b1 * a22 - b2 * a12) / det, (a11 * b2 - a12 * b1) / det, height};
}

DrawnSurface drawnSurface(const ShapeDesc& described, const ShapeSamples& samples,
                          const BuiltShape& built, double spacing) {
  DrawnSurface out;
  if (samples.position.empty()) return out;
  tessellate(described, samples, built, spacing, out);
  dropUnusedVertices(out);
  anchorVertices(samples, spacing, out);
  orientOutward(samples, spacing, out);
  return out;
}

}  // namespace sph::objects
