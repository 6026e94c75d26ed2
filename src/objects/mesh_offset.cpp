#include <cmath>
#include <vector>

#include "objects/math3d.hpp"
#include "objects/mesh.hpp"

namespace sph::objects {

namespace {

// Solves (A + εI) x = b for a symmetric positive semi-definite 3×3 A by Cramer's rule.
DVec3 solveRegularised(const double (&a)[3][3], DVec3 b, double epsilon) {
  double m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = a[i][j] + (i == j ? epsilon : 0.0);
  const auto det = [](const double(&q)[3][3]) {
    return q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) -
           q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
           q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
  };
  const double d = det(m);
  const double rhs[3] = {b.x, b.y, b.z};
  double x[3];
  for (int c = 0; c < 3; ++c) {
    double replaced[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) replaced[i][j] = j == c ? rhs[i] : m[i][j];
    x[c] = det(replaced) / d;
  }
  return {x[0], x[1], x[2]};
}

}  // namespace

// Each vertex moves by the δ that puts every adjacent triangle's plane `distance` along its
// normal: least squares over Σ (n·δ − distance)², which is exact at a crease (two planes) and a
// box corner (three), and the normal itself on a flat vertex, where the small regularisation
// keeps the tangential part at zero.
TriangleMesh offsetAlongNormals(const TriangleMesh& mesh, double distance) {
  std::vector<std::array<std::array<double, 3>, 3>> normalProducts(mesh.vertices.size());
  std::vector<DVec3> normalSums(mesh.vertices.size());
  std::vector<int> adjacent(mesh.vertices.size(), 0);
  for (const auto& triangle : mesh.triangles) {
    const DVec3 a = toD(mesh.vertices[triangle[0]]);
    const DVec3 n =
        normalized(cross(toD(mesh.vertices[triangle[1]]) - a, toD(mesh.vertices[triangle[2]]) - a));
    if (dot(n, n) == 0.0) continue;  // degenerate: no plane to keep
    const double nv[3] = {n.x, n.y, n.z};
    for (std::uint32_t v : triangle) {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) normalProducts[v][i][j] += nv[i] * nv[j];
      normalSums[v] += n;
      ++adjacent[v];
    }
  }
  TriangleMesh offset = mesh;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (adjacent[v] == 0) continue;
    double a[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) a[i][j] = normalProducts[v][i][j];
    const DVec3 delta = solveRegularised(a, normalSums[v] * distance, 1e-3 * adjacent[v]);
    offset.vertices[v] = toF(toD(mesh.vertices[v]) + delta);
  }
  return offset;
}

}  // namespace sph::objects
