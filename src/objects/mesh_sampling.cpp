// Points on the surface of a triangle mesh, for object particles.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "objects/mesh.hpp"
#include "sph/error.hpp"

namespace sph::objects {

namespace {

Vec3 cross(Vec3 a, Vec3 b) {
  return Vec3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

Vec3 corner(const TriangleMesh& mesh, std::size_t t, int i) {
  return mesh.vertices[mesh.triangles[t][i]];
}

// Twice the area times the unit normal (right-hand winding).
Vec3 areaNormal(const TriangleMesh& mesh, std::size_t t) {
  const Vec3 a = corner(mesh, t, 0);
  return cross(corner(mesh, t, 1) - a, corner(mesh, t, 2) - a);
}

void checkSpacing(float spacing, const char* what) {
  if (!(spacing > 0.0f) || !std::isfinite(spacing)) {
    throw InputError(std::string(what) + ": spacing must be a positive number, got " +
                     std::to_string(spacing));
  }
}

// Accepted points in a hash grid so that the spacing check only looks at nearby points.
class SpacedPointSet {
 public:
  // `cellSize` must be at least the largest distance passed to insertIfClear.
  explicit SpacedPointSet(float cellSize) : inverseCell_(1.0f / cellSize) {}

  // Adds p unless an accepted point lies closer than minDistance.
  void insertIfClear(Vec3 p, Vec3 normal, float minDistance) {
    const long long cx = cellOf(p.x), cy = cellOf(p.y), cz = cellOf(p.z);
    for (long long dz = -1; dz <= 1; ++dz)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dx = -1; dx <= 1; ++dx) {
          const auto found = cells_.find(key(cx + dx, cy + dy, cz + dz));
          if (found == cells_.end()) continue;
          for (std::uint32_t i : found->second) {
            if (lengthSquared(points_.position[i] - p) < minDistance * minDistance) return;
          }
        }
    cells_[key(cx, cy, cz)].push_back(static_cast<std::uint32_t>(points_.position.size()));
    points_.position.push_back(p);
    points_.normal.push_back(normal);
  }

  SampledPoints take() { return std::move(points_); }

 private:
  long long cellOf(float v) const { return static_cast<long long>(std::floor(v * inverseCell_)); }
  // Wrapping far-away cells onto one key only costs extra distance checks.
  static std::uint64_t key(long long x, long long y, long long z) {
    constexpr std::uint64_t kMask = (1u << 21) - 1;
    return (static_cast<std::uint64_t>(x) & kMask) | (static_cast<std::uint64_t>(y) & kMask) << 21 |
           (static_cast<std::uint64_t>(z) & kMask) << 42;
  }

  float inverseCell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
  SampledPoints points_;
};

// A triangle in a frame where its longest edge runs from the origin along +x and the third
// corner sits at (apexX, height) with 0 <= apexX <= baseLength.
struct TriangleFrame {
  Vec3 origin, alongBase, towardApex, normal;
  float baseLength, apexX, height;

  // The x range the triangle covers at height y, narrowing toward the apex.
  float xMin(float y) const { return apexX * y / height; }
  float xMax(float y) const { return baseLength - (baseLength - apexX) * y / height; }
  Vec3 at(float x, float y) const { return origin + alongBase * x + towardApex * y; }
};

TriangleFrame frameOf(const TriangleMesh& mesh, std::size_t t, Vec3 unitNormal) {
  int base = 0;
  float longest = -1.0f;
  for (int i = 0; i < 3; ++i) {
    const float l = length(corner(mesh, t, (i + 1) % 3) - corner(mesh, t, i));
    if (l > longest) {
      longest = l;
      base = i;
    }
  }
  TriangleFrame f{};
  f.origin = corner(mesh, t, base);
  f.normal = unitNormal;
  f.baseLength = longest;
  f.alongBase = (corner(mesh, t, (base + 1) % 3) - f.origin) / longest;
  f.towardApex = cross(unitNormal, f.alongBase);
  const Vec3 apex = corner(mesh, t, (base + 2) % 3) - f.origin;
  f.apexX = std::clamp(dot(apex, f.alongBase), 0.0f, longest);
  f.height = dot(apex, f.towardApex);
  return f;
}

// Pass 1: every mesh vertex, then points at most `spacing` apart along every edge, so that
// creases and rims are sampled exactly. The lowest-numbered triangle lends its normal.
void sampleVerticesAndEdges(const TriangleMesh& mesh, const std::vector<Vec3>& normals,
                            float spacing, float minDistance, SpacedPointSet& points) {
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> vertexOwner(mesh.vertices.size(), kNone);
  struct Edge {
    std::uint32_t lo, hi, triangle;
  };
  std::vector<Edge> edges;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (lengthSquared(normals[t]) == 0.0f) continue;  // no area, nothing to sample
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[t][i], b = mesh.triangles[t][(i + 1) % 3];
      if (vertexOwner[a] == kNone) vertexOwner[a] = t;
      edges.push_back({std::min(a, b), std::max(a, b), t});
    }
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (vertexOwner[v] != kNone) {
      points.insertIfClear(mesh.vertices[v], normals[vertexOwner[v]], minDistance);
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return a.lo != b.lo ? a.lo < b.lo : a.hi != b.hi ? a.hi < b.hi : a.triangle < b.triangle;
  });
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (e > 0 && edges[e].lo == edges[e - 1].lo && edges[e].hi == edges[e - 1].hi) continue;
    const Vec3 a = mesh.vertices[edges[e].lo], b = mesh.vertices[edges[e].hi];
    // The small allowance keeps an edge of exactly n spacings from getting n + 1 segments.
    const int segments = std::max(1, static_cast<int>(std::ceil(length(b - a) / spacing - 1e-3f)));
    for (int k = 1; k < segments; ++k) {
      points.insertIfClear(a + (b - a) * (static_cast<float>(k) / segments),
                           normals[edges[e].triangle], minDistance);
    }
  }
}

// Pass 2: a hexagonal lattice of edge `spacing` in each triangle, rows parallel to its longest
// edge. Its largest gap, spacing / sqrt(3), stays below the fill distance of pass 3, so the
// fill adds nothing inside a lattice.
void sampleTriangleLattices(const std::vector<TriangleFrame>& frames, float spacing,
                            float clearance, SpacedPointSet& points) {
  const float rowStep = spacing * std::sqrt(3.0f) / 2.0f;
  for (const TriangleFrame& f : frames) {
    for (int row = 1; row * rowStep < f.height; ++row) {
      const float y = row * rowStep;
      const float offset = (row % 2) * 0.5f * spacing;
      const long long first = static_cast<long long>(std::ceil((f.xMin(y) - offset) / spacing));
      const long long last = static_cast<long long>(std::floor((f.xMax(y) - offset) / spacing));
      for (long long i = first; i <= last; ++i) {
        points.insertIfClear(f.at(offset + i * spacing, y), f.normal, clearance);
      }
    }
  }
}

// Pass 3: where seams between triangles left gaps wider than fillDistance, candidates on a
// fine grid (rows and points at most `step` apart, so every surface point is within
// sqrt(1.25) step of one) fill them. Every surface point ends up within
// fillDistance + sqrt(1.25) step of a sample.
void fillGaps(const std::vector<TriangleFrame>& frames, float step, float fillDistance,
              SpacedPointSet& points) {
  for (const TriangleFrame& f : frames) {
    const int rows = std::max(1, static_cast<int>(std::ceil(f.height / step)));
    for (int row = 0; row <= rows; ++row) {
      const float y = f.height * row / rows;
      const float x0 = f.xMin(y), width = std::max(0.0f, f.xMax(y) - x0);
      const int columns = static_cast<int>(std::ceil(width / step));
      for (int column = 0; column <= columns; ++column) {
        const float x = columns == 0 ? x0 : x0 + width * column / columns;
        points.insertIfClear(f.at(x, y), f.normal, fillDistance);
      }
    }
  }
}

}  // namespace

SampledPoints sampleMeshSurface(const TriangleMesh& mesh, float spacing) {
  checkSpacing(spacing, "mesh surface sampling");
  // No two points closer than minDistance. Lattice points keep a wider berth from points
  // already placed, so that seams get fewer crowded pairs and the gap fill closes what is left.
  // Every surface point ends up within minDistance + sqrt(1.25) fillStep = 0.74 spacing of a
  // sample (see fillGaps).
  const float minDistance = 0.65f * spacing;
  const float latticeClearance = 0.7f * spacing;
  const float fillStep = 0.08f * spacing;
  std::vector<Vec3> normals(mesh.triangles.size());
  std::vector<TriangleFrame> frames;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 n = areaNormal(mesh, t);
    const float twiceArea = length(n);
    if (!(twiceArea > 0.0f)) continue;
    normals[t] = n / twiceArea;
    frames.push_back(frameOf(mesh, t, normals[t]));
  }
  SpacedPointSet points(latticeClearance);
  sampleVerticesAndEdges(mesh, normals, spacing, minDistance, points);
  sampleTriangleLattices(frames, spacing, latticeClearance, points);
  fillGaps(frames, fillStep, minDistance, points);
  return points.take();
}

}  // namespace sph::objects
