// The inside of a closed triangle mesh: closedness, point containment, and the lattice points
// inside (sampleMeshSolid). Surface sampling is in mesh_sampling.cpp, reading in mesh_io.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "objects/mesh.hpp"
#include "sph/core/constants.hpp"
#include "sph/error.hpp"

namespace sph::objects {

namespace {

Vec3 corner(const TriangleMesh& mesh, std::size_t t, int i) {
  return mesh.vertices[mesh.triangles[t][i]];
}

Vec3 unitNormal(const TriangleMesh& mesh, std::size_t t) {
  const Vec3 u = corner(mesh, t, 1) - corner(mesh, t, 0),
             v = corner(mesh, t, 2) - corner(mesh, t, 0);
  const Vec3 n{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
  return n / length(n);
}

Vec3 closestPointOnTriangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  // Voronoi regions of the corners, then the edges, then the face (Ericson, Real-Time
  // Collision Detection §5.1.5).
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return a;
  const Vec3 bp = p - b;
  const float d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return b;
  const Vec3 cp = p - c;
  const float d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return c;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const float denominator = 1.0f / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

// A bounding-volume tree over the triangles for nearest-surface-point queries.
class TriangleTree {
 public:
  explicit TriangleTree(const TriangleMesh& mesh) : mesh_(mesh) {
    order_.resize(mesh.triangles.size());
    for (std::uint32_t t = 0; t < order_.size(); ++t) order_[t] = t;
    nodes_.push_back({});
    build(0, 0, static_cast<std::uint32_t>(order_.size()));
  }

  // The closest point of the mesh to p, and the triangle it lies on.
  Vec3 closestPoint(Vec3 p, std::uint32_t& triangle) const {
    float best = std::numeric_limits<float>::infinity();
    Vec3 closest = p;
    std::uint32_t stack[64];
    int depth = 0;
    stack[depth++] = 0;
    while (depth > 0) {
      const Node& node = nodes_[stack[--depth]];
      if (boxDistanceSquared(node, p) >= best) continue;
      if (node.count > 0) {
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
          const std::uint32_t t = order_[i];
          const Vec3 q = closestPointOnTriangle(p, corner(mesh_, t, 0), corner(mesh_, t, 1),
                                                corner(mesh_, t, 2));
          const float d = lengthSquared(q - p);
          if (d < best) {
            best = d;
            closest = q;
            triangle = t;
          }
        }
        continue;
      }
      // The nearer child goes on top so that it tightens `best` first.
      const bool leftNearer = boxDistanceSquared(nodes_[node.first], p) <=
                              boxDistanceSquared(nodes_[node.first + 1], p);
      stack[depth++] = node.first + (leftNearer ? 1 : 0);
      stack[depth++] = node.first + (leftNearer ? 0 : 1);
    }
    return closest;
  }

 private:
  struct Node {
    Vec3 lo, hi;
    std::uint32_t first, count;  // leaf: order_[first, first + count); inner: children first, +1
  };
  static constexpr std::uint32_t kLeafSize = 4;

  Vec3 centroid(std::uint32_t t) const {
    return (corner(mesh_, t, 0) + corner(mesh_, t, 1) + corner(mesh_, t, 2)) / 3.0f;
  }

  void build(std::size_t index, std::uint32_t begin, std::uint32_t end) {
    Vec3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
            std::numeric_limits<float>::max()};
    Vec3 hi = -lo;
    for (std::uint32_t i = begin; i < end; ++i)
      for (int k = 0; k < 3; ++k) {
        const Vec3 v = corner(mesh_, order_[i], k);
        lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
        hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
      }
    nodes_[index].lo = lo;
    nodes_[index].hi = hi;
    if (end - begin <= kLeafSize) {
      nodes_[index].first = begin;
      nodes_[index].count = end - begin;
      return;
    }
    // Median split along the longest side keeps the depth near log2(n), well under the stack.
    const Vec3 size = hi - lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    const auto along = [&](std::uint32_t t) {
      const Vec3 c = centroid(t);
      return axis == 0 ? c.x : axis == 1 ? c.y : c.z;
    };
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return along(a) < along(b); });
    const auto children = static_cast<std::uint32_t>(nodes_.size());
    nodes_[index].first = children;
    nodes_[index].count = 0;
    nodes_.push_back({});
    nodes_.push_back({});
    build(children, begin, middle);
    build(children + 1, middle, end);
  }

  static float boxDistanceSquared(const Node& node, Vec3 p) {
    const Vec3 outside{std::max({node.lo.x - p.x, 0.0f, p.x - node.hi.x}),
                       std::max({node.lo.y - p.y, 0.0f, p.y - node.hi.y}),
                       std::max({node.lo.z - p.z, 0.0f, p.z - node.hi.z})};
    return lengthSquared(outside);
  }

  const TriangleMesh& mesh_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

// Twice the signed area of (a, b, p) in the y-z plane, and the side of the edge that p counts
// as being on. The edge is always evaluated from its lower-numbered vertex, so two triangles
// sharing it see exactly opposite values.
struct EdgeSide {
  double value;
  bool positive;
};

EdgeSide edgeSide(const TriangleMesh& mesh, std::uint32_t i, std::uint32_t j, double py,
                  double pz) {
  const bool flip = i > j;
  const Vec3 a = mesh.vertices[flip ? j : i], b = mesh.vertices[flip ? i : j];
  const double value = (double{b.y} - a.y) * (pz - a.z) - (double{b.z} - a.z) * (py - a.y);
  // On the edge's line itself, decide as if p were moved by (eps, eps^2) in (y, z): every
  // triangle sees the same moved point, so a ray through an edge or a vertex crosses the
  // surface exactly once there (simulation of simplicity, Edelsbrunner and Muecke 1990).
  const double tieBreak = b.z != a.z ? -(double{b.z} - a.z) : double{b.y} - a.y;
  const bool positive = value != 0.0 ? value > 0.0 : tieBreak > 0.0;
  return {flip ? -value : value, flip ? !positive : positive};
}

// Where the ray along +x through (y, z) crosses triangle t, if it does.
bool rayCrossing(const TriangleMesh& mesh, std::size_t t, double y, double z, float& x) {
  const auto& v = mesh.triangles[t];
  const EdgeSide s0 = edgeSide(mesh, v[1], v[2], y, z);
  const EdgeSide s1 = edgeSide(mesh, v[2], v[0], y, z);
  const EdgeSide s2 = edgeSide(mesh, v[0], v[1], y, z);
  if (s0.positive != s1.positive || s1.positive != s2.positive) return false;
  // A triangle seen edge-on has no inside, whatever the tie-break says.
  const double sum = s0.value + s1.value + s2.value;
  if (sum == 0.0) return false;
  const Vec3 a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
  x = static_cast<float>((s0.value * a.x + s1.value * b.x + s2.value * c.x) / sum);
  return true;
}

// The cubic lattice min + spacing (i + 1/2, j + 1/2, k + 1/2) over the mesh's bounding box.
struct Lattice {
  Vec3 first;
  float spacing;
  long long nx, ny, nz;

  float y(long long j) const { return first.y + j * spacing; }
  float z(long long k) const { return first.z + k * spacing; }
};

Lattice latticeOver(const TriangleMesh& mesh, float spacing) {
  Vec3 lo = mesh.vertices[mesh.triangles[0][0]], hi = lo;
  for (const auto& t : mesh.triangles)
    for (std::uint32_t i : t) {
      const Vec3 v = mesh.vertices[i];
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
  // Points whose centre passes the box's far side cannot be inside.
  const auto count = [&](float extent) {
    return static_cast<long long>(std::floor(extent / spacing + 0.5f));
  };
  return {lo + Vec3{spacing, spacing, spacing} * 0.5f, spacing, count(hi.x - lo.x),
          count(hi.y - lo.y), count(hi.z - lo.z)};
}

struct Crossing {
  long long row;  // k * ny + j
  float x;
  bool operator<(const Crossing& o) const { return row != o.row ? row < o.row : x < o.x; }
};

// Where each lattice row (a line along x) crosses the surface, sorted by row and then x.
std::vector<Crossing> rowCrossings(const TriangleMesh& mesh, const Lattice& lattice) {
  const float h = lattice.spacing;
  // One row of slack each way: rounding must not drop a row through a vertex.
  const auto firstRow = [&](float low, float start) {
    return std::max(0LL, static_cast<long long>(std::ceil((low - start) / h)) - 1);
  };
  const auto lastRow = [&](float high, float start, long long n) {
    return std::min(n - 1, static_cast<long long>(std::floor((high - start) / h)) + 1);
  };
  std::vector<Crossing> crossings;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
    const long long j0 = firstRow(std::min({a.y, b.y, c.y}), lattice.first.y);
    const long long j1 = lastRow(std::max({a.y, b.y, c.y}), lattice.first.y, lattice.ny);
    const long long k0 = firstRow(std::min({a.z, b.z, c.z}), lattice.first.z);
    const long long k1 = lastRow(std::max({a.z, b.z, c.z}), lattice.first.z, lattice.nz);
    for (long long k = k0; k <= k1; ++k)
      for (long long j = j0; j <= j1; ++j) {
        float x = 0.0f;
        if (rayCrossing(mesh, t, lattice.y(j), lattice.z(k), x)) {
          crossings.push_back({k * lattice.ny + j, x});
        }
      }
  }
  std::sort(crossings.begin(), crossings.end());
  return crossings;
}

// A lattice point is inside when an odd number of its row's crossings lie before it.
std::vector<Vec3> latticePointsInside(const TriangleMesh& mesh, const Lattice& lattice,
                                      const std::vector<Crossing>& crossings) {
  std::vector<Vec3> inside;
  for (std::size_t begin = 0; begin < crossings.size();) {
    std::size_t end = begin;
    while (end < crossings.size() && crossings[end].row == crossings[begin].row) ++end;
    const long long row = crossings[begin].row;
    const float y = lattice.y(row % lattice.ny), z = lattice.z(row / lattice.ny);
    // An odd count means rounding broke the crossing rule somewhere on this row.
    const bool trustParity = (end - begin) % 2 == 0;
    std::size_t passed = begin;
    for (long long i = 0; i < lattice.nx; ++i) {
      const Vec3 p{lattice.first.x + i * lattice.spacing, y, z};
      while (passed < end && crossings[passed].x < p.x) ++passed;
      if (trustParity ? (passed - begin) % 2 == 1 : meshContains(mesh, p)) inside.push_back(p);
    }
    begin = end;
  }
  return inside;
}

// Unit vectors from each point toward the nearest point of the surface.
std::vector<Vec3> directionsToSurface(const TriangleMesh& mesh, const std::vector<Vec3>& points,
                                      float spacing) {
  const TriangleTree tree(mesh);
  std::vector<Vec3> directions(points.size());
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < static_cast<long long>(points.size()); ++i) {
    std::uint32_t triangle = 0;
    const Vec3 toSurface = tree.closestPoint(points[i], triangle) - points[i];
    const float distance = length(toSurface);
    // On the surface itself there is no direction to the nearest point; the face's will do.
    directions[i] = distance > 1e-6f * spacing ? toSurface / distance : unitNormal(mesh, triangle);
  }
  return directions;
}

}  // namespace

bool isClosed(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return false;
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t a = t[i], b = t[(i + 1) % 3];
      edges.push_back(std::min(a, b) << 32 | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i != 2) return false;
    i = j;
  }
  return true;
}

SampledPoints sampleMeshSolid(const TriangleMesh& mesh, float spacing) {
  if (!(spacing > 0.0f) || !std::isfinite(spacing)) {
    throw InputError("mesh solid sampling: spacing must be a positive number, got " +
                     std::to_string(spacing));
  }
  if (!isClosed(mesh)) {
    throw InputError(
        "mesh solid sampling needs a closed mesh: every edge shared by exactly two triangles");
  }
  const Lattice lattice = latticeOver(mesh, spacing);
  SampledPoints solid;
  solid.position = latticePointsInside(mesh, lattice, rowCrossings(mesh, lattice));
  solid.normal = directionsToSurface(mesh, solid.position, spacing);
  return solid;
}

bool meshContains(const TriangleMesh& mesh, Vec3 p) {
  // Generalized winding number (Jacobson et al. 2013): the solid angles of all triangles seen
  // from p sum to 4 pi inside a closed mesh and to 0 outside, with no special cases for rays
  // through edges or vertices. Each solid angle is from Van Oosterom and Strackee (1983).
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    double r[3][3];
    double len[3];
    for (int i = 0; i < 3; ++i) {
      const Vec3 v = mesh.vertices[t[i]] - p;
      r[i][0] = v.x, r[i][1] = v.y, r[i][2] = v.z;
      len[i] = std::sqrt(r[i][0] * r[i][0] + r[i][1] * r[i][1] + r[i][2] * r[i][2]);
    }
    const auto dot3 = [&](int i, int j) {
      return r[i][0] * r[j][0] + r[i][1] * r[j][1] + r[i][2] * r[j][2];
    };
    const double triple = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
                          r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                          r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
    const double denominator =
        len[0] * len[1] * len[2] + dot3(0, 1) * len[2] + dot3(0, 2) * len[1] + dot3(1, 2) * len[0];
    total += 2.0 * std::atan2(triple, denominator);
  }
  constexpr double kFourPi = 4.0 * kPi;
  // Either winding counts, so an inside-out mesh still has an inside.
  return std::abs(total / kFourPi) > 0.5;
}

double signedVolume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    // a · (b × c) / 6 per triangle, in double: a tetrahedron with the origin.
    const double bc[3] = {double(b.y) * c.z - double(b.z) * c.y,
                          double(b.z) * c.x - double(b.x) * c.z,
                          double(b.x) * c.y - double(b.y) * c.x};
    volume += (a.x * bc[0] + a.y * bc[1] + a.z * bc[2]) / 6.0;
  }
  return volume;
}

}  // namespace sph::objects
