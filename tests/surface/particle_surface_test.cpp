// Surface meshes of resting fluid (apps/surface): closed, manifold and consistently oriented,
// enclosing the fluid's volume, a tank's top flat; and written in each format.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "mesh_files.hpp"
#include "particle_surface.hpp"
#include "sph/error.hpp"
#include "triangle_mesh.hpp"

namespace sph::surface {
namespace {

constexpr double kSpacing = 0.01;

// Particles on a lattice of kSpacing, at the centres of the cells `inside` keeps: each stands
// for a cell's volume.
template <class Inside>
std::vector<float> lattice(int cells, Inside&& inside) {
  std::vector<float> points;
  for (int i = -cells; i < cells; ++i)
    for (int j = -cells; j < cells; ++j)
      for (int k = -cells; k < cells; ++k) {
        const double x = (i + 0.5) * kSpacing, y = (j + 0.5) * kSpacing, z = (k + 0.5) * kSpacing;
        if (inside(x, y, z)) points.insert(points.end(), {float(x), float(y), float(z)});
      }
  return points;
}

double latticeVolume(const std::vector<float>& points) {
  return double(points.size() / 3) * kSpacing * kSpacing * kSpacing;
}

SurfaceSettings defaults() {
  SurfaceSettings s;
  s.spacing = kSpacing;
  return s;
}

void expectWatertight(const MeshCheck& check) {
  EXPECT_EQ(check.openEdges, 0u);
  EXPECT_EQ(check.overusedEdges, 0u);
  EXPECT_EQ(check.misorientedEdges, 0u);
}

TEST(ParticleSurface, ARestingDropIsClosedAndEnclosesItsVolume) {
  const double radius = 10 * kSpacing;
  const std::vector<float> drop = lattice(
      11, [&](double x, double y, double z) { return x * x + y * y + z * z < radius * radius; });
  const TriangleMesh mesh = reconstructSurface(drop, defaults());
  const MeshCheck check = checkMesh(mesh);
  ASSERT_GT(mesh.triangleCount(), 1000u);
  expectWatertight(check);
  RecordProperty("volume_over_fluid", std::to_string(check.volume / latticeVolume(drop)));
  EXPECT_NEAR(check.volume, latticeVolume(drop), 0.05 * latticeVolume(drop));
}

TEST(ParticleSurface, ARestingTankIsClosedWithAFlatTop) {
  // 0.3 m × 0.15 m × 0.2 m of water, its top at y = 0.05 m.
  const std::vector<float> tank = lattice(15, [](double x, double y, double z) {
    return std::abs(x) < 0.15 && y > -0.1 && y < 0.05 && std::abs(z) < 0.1;
  });
  const TriangleMesh mesh = reconstructSurface(tank, defaults());
  const MeshCheck check = checkMesh(mesh);
  expectWatertight(check);
  RecordProperty("volume_over_fluid", std::to_string(check.volume / latticeVolume(tank)));
  EXPECT_NEAR(check.volume, latticeVolume(tank), 0.05 * latticeVolume(tank));
  // The top away from the edges (which the smoothing rounds): flat, at the fluid's top.
  double lowest = 1e9, highest = -1e9;
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    const float* p = &mesh.vertices[3 * v];
    if (p[1] < 0.0f || std::abs(p[0]) > 0.12f || std::abs(p[2]) > 0.07f) continue;
    lowest = std::min(lowest, double(p[1]));
    highest = std::max(highest, double(p[1]));
  }
  ASSERT_LT(lowest, highest);
  RecordProperty("top_spread_over_spacing", std::to_string((highest - lowest) / kSpacing));
  RecordProperty("top_over_spacing", std::to_string((0.5 * (lowest + highest) - 0.05) / kSpacing));
  EXPECT_LT(highest - lowest, kSpacing);
  EXPECT_NEAR(0.5 * (lowest + highest), 0.05, 0.25 * kSpacing);
}

TEST(ParticleSurface, NoParticlesNoMesh) {
  EXPECT_EQ(reconstructSurface({}, defaults()).triangleCount(), 0u);
  SurfaceSettings bad = defaults();
  bad.spacing = 0.0;
  EXPECT_THROW(reconstructSurface({0.0f, 0.0f, 0.0f}, bad), std::invalid_argument);
}

TEST(MeshCheck, FindsAnOpenEdgeAndAFlippedTriangle) {
  // A tetrahedron, outward: volume 1/6.
  TriangleMesh tetrahedron{{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1},
                           {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}};
  MeshCheck closed = checkMesh(tetrahedron);
  expectWatertight(closed);
  EXPECT_NEAR(closed.volume, 1.0 / 6.0, 1e-9);
  TriangleMesh flipped = tetrahedron;
  std::swap(flipped.triangles[1], flipped.triangles[2]);
  EXPECT_EQ(checkMesh(flipped).misorientedEdges, 3u);
  TriangleMesh open = tetrahedron;
  open.triangles.resize(9);
  EXPECT_EQ(checkMesh(open).openEdges, 3u);
}

std::string readAll(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(MeshFiles, EachFormatHoldsTheMesh) {
  const TriangleMesh mesh{{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1},
                          {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}};
  const std::filesystem::path dir =
      std::filesystem::path(testing::TempDir()) / "sph_mesh_files_test";
  std::filesystem::create_directories(dir);
  writeMesh(dir / "m.vtp", mesh, MeshFormat::Vtp);
  writeMesh(dir / "m.obj", mesh, MeshFormat::Obj);
  writeMesh(dir / "m.ply", mesh, MeshFormat::Ply);
  const std::string vtp = readAll(dir / "m.vtp");
  EXPECT_NE(vtp.find("NumberOfPoints=\"4\" NumberOfPolys=\"4\""), std::string::npos);
  EXPECT_NE(vtp.find("Name=\"offsets\""), std::string::npos);
  const std::string obj = readAll(dir / "m.obj");
  EXPECT_NE(obj.find("f 1 3 2\n"), std::string::npos);  // OBJ counts vertices from 1
  const std::string ply = readAll(dir / "m.ply");
  const std::string header = "element vertex 4\n";
  ASSERT_NE(ply.find(header), std::string::npos);
  const std::size_t body = ply.find("end_header\n") + 11;
  EXPECT_EQ(ply.size() - body, 4 * 3 * sizeof(float) + 4 * (1 + 3 * sizeof(std::uint32_t)));
  EXPECT_FALSE(std::filesystem::exists(dir / "m.ply.partial"));
  EXPECT_THROW(writeMesh(dir / "missing" / "m.vtp", mesh, MeshFormat::Vtp), OutputError);
}

}  // namespace
}  // namespace sph::surface
