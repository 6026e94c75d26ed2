#include "objects/mesh.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include "sph/error.hpp"

namespace sph::objects {
namespace {

namespace fs = std::filesystem;

// A scratch folder per test, removed afterwards.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("sph_mesh_test_" + std::to_string(getpid()) + "_" + info->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  fs::path write(const std::string& name, const std::string& content) const {
    const fs::path file = path_ / name;
    std::ofstream(file, std::ios::binary) << content;
    return file;
  }
  fs::path path() const { return path_; }

 private:
  fs::path path_;
};

Vec3 cross(Vec3 a, Vec3 b) {
  return Vec3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Corner i of the cube [0, side]^3 has x, y, z from bits 0, 1, 2 of i.
std::vector<Vec3> cubeCorners(float side) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(Vec3{side * (i & 1), side * ((i >> 1) & 1), side * ((i >> 2) & 1)});
  return corners;
}

// Faces -x, +x, -y, +y, -z, +z, counter-clockwise seen from outside.
const int kCubeQuads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                              {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

TriangleMesh makeCube(float side, int faces = 6) {
  TriangleMesh mesh;
  mesh.vertices = cubeCorners(side);
  for (int f = 0; f < faces; ++f) {
    const auto* q = kCubeQuads[f];
    mesh.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2])});
    mesh.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
  }
  return mesh;
}

// |x| + |y| + |z| <= radius, outward winding.
TriangleMesh makeOctahedron(float r) {
  TriangleMesh mesh;
  mesh.vertices = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
  for (std::uint32_t x : {0u, 1u})
    for (std::uint32_t y : {2u, 3u})
      for (std::uint32_t z : {4u, 5u}) {
        // (x, y, z) is counter-clockwise from outside when an even number of signs is negative.
        const bool flip = (x + y + z) % 2 == 1;
        mesh.triangles.push_back(flip ? std::array<std::uint32_t, 3>{x, z, y}
                                      : std::array<std::uint32_t, 3>{x, y, z});
      }
  return mesh;
}

// The regular icosahedron with corners (0, +-1, +-phi) and cyclic permutations, wound outward.
TriangleMesh makeIcosahedron() {
  const float phi = (1.0f + std::sqrt(5.0f)) / 2.0f;
  TriangleMesh mesh;
  for (float a : {-1.0f, 1.0f})
    for (float b : {-phi, phi}) {
      mesh.vertices.push_back({0, a, b});
      mesh.vertices.push_back({a, b, 0});
      mesh.vertices.push_back({b, 0, a});
    }
  // Faces are the triples of corners at edge length 2; orient each away from the centre.
  const std::size_t n = mesh.vertices.size();
  const auto isEdge = [&](std::size_t i, std::size_t j) {
    return std::abs(length(mesh.vertices[i] - mesh.vertices[j]) - 2.0f) < 1e-4f;
  };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      for (std::uint32_t k = j + 1; k < n; ++k) {
        if (!isEdge(i, j) || !isEdge(j, k) || !isEdge(i, k)) continue;
        const Vec3 a = mesh.vertices[i], b = mesh.vertices[j], c = mesh.vertices[k];
        const bool outward = dot(cross(b - a, c - a), a) > 0.0f;
        mesh.triangles.push_back(outward ? std::array<std::uint32_t, 3>{i, j, k}
                                         : std::array<std::uint32_t, 3>{i, k, j});
      }
  return mesh;
}

Vec3 unitNormal(const TriangleMesh& mesh, std::size_t t) {
  const auto& v = mesh.triangles[t];
  const Vec3 n =
      cross(mesh.vertices[v[1]] - mesh.vertices[v[0]], mesh.vertices[v[2]] - mesh.vertices[v[0]]);
  return n / length(n);
}

std::string cubeObjWithQuads() {
  std::string text;
  for (const Vec3& v : cubeCorners(1.0f)) {
    text +=
        "v " + std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + "\n";
  }
  for (const auto& q : kCubeQuads) {
    text += "f " + std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " +
            std::to_string(q[2] + 1) + " " + std::to_string(q[3] + 1) + "\n";
  }
  return text;
}

std::string cubeAsciiStl() {
  const TriangleMesh cube = makeCube(1.0f);
  std::string text = "solid cube\n";
  for (const auto& t : cube.triangles) {
    text += "  facet normal 0 0 0\n    outer loop\n";
    for (std::uint32_t i : t) {
      const Vec3 v = cube.vertices[i];
      text += "      vertex " + std::to_string(v.x) + " " + std::to_string(v.y) + " " +
              std::to_string(v.z) + "\n";
    }
    text += "    endloop\n  endfacet\n";
  }
  return text + "endsolid cube\n";
}

void appendLittleEndian(std::string& bytes, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes += static_cast<char>((value >> (8 * i)) & 0xff);
}

void appendFloat(std::string& bytes, float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  appendLittleEndian(bytes, bits);
}

// The header starts with "solid" on purpose: the size, not the header, says it is binary.
std::string cubeBinaryStl() {
  const TriangleMesh cube = makeCube(1.0f);
  std::string bytes = "solid cube, binary all the same";
  bytes.resize(80, ' ');
  appendLittleEndian(bytes, static_cast<std::uint32_t>(cube.triangles.size()));
  for (const auto& t : cube.triangles) {
    for (int i = 0; i < 3; ++i) appendFloat(bytes, 0.0f);
    for (std::uint32_t i : t) {
      appendFloat(bytes, cube.vertices[i].x);
      appendFloat(bytes, cube.vertices[i].y);
      appendFloat(bytes, cube.vertices[i].z);
    }
    bytes += std::string(2, '\0');
  }
  return bytes;
}

void expectUnitCube(const TriangleMesh& mesh) {
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_TRUE(isClosed(mesh));
  EXPECT_NEAR(signedVolume(mesh), 1.0, 1e-6);
}

TEST(MeshLoad, ObjWithQuads) {
  ScratchDir dir;
  expectUnitCube(loadMesh(dir.write("cube.obj", cubeObjWithQuads())));
}

TEST(MeshLoad, ObjWithSlashFormsNegativeIndicesAndOtherRecords) {
  ScratchDir dir;
  // CRLF line ends, a w coordinate, and every face-corner form; the last faces count from the
  // end: -8 is vertex 1.
  const std::string text =
      "# exported cube\r\nmtllib cube.mtl\r\no Cube\r\n"
      "v 0 0 0 1.0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 0\r\n"
      "v 0 0 1\r\nv 1 0 1\r\nv 0 1 1\r\nv +1 1 1   # last corner\r\n"
      "vt 0 0\r\nvt 1 0\r\nvt 1 1\r\nvt 0 1\r\nvn 0 0 1\r\ng faces\r\ns off\r\nusemtl grey\r\n"
      "f 1/1/1 5/2/1 7/3/1 3/4/1\r\n"
      "f 2/1 4/2 8/3 6/4\r\n"
      "f 1//1 2//1 6//1 5//1\r\n"
      "f -6/1/1 -2/2/1 -1/3/1 -5/4/1\r\n"
      "f -8//1 -6//1 -5//1 -7//1\r\n"
      "f -4 -3 -1 -2\r\n";
  expectUnitCube(loadMesh(dir.write("cube.obj", text)));
}

TEST(MeshLoad, AsciiStlIsWelded) {
  ScratchDir dir;
  expectUnitCube(loadMesh(dir.write("cube.stl", cubeAsciiStl())));
}

TEST(MeshLoad, BinaryStlWithSolidHeaderIsWelded) {
  ScratchDir dir;
  const std::string bytes = cubeBinaryStl();
  ASSERT_EQ(bytes.size(), 84u + 50u * 12u);
  // Upper-case extensions are accepted too.
  expectUnitCube(loadMesh(dir.write("CUBE.STL", bytes)));
}

TEST(MeshClosed, OpenAndEmptyMeshesAreNotClosed) {
  EXPECT_TRUE(isClosed(makeCube(1.0f)));
  EXPECT_FALSE(isClosed(makeCube(1.0f, 5)));
  EXPECT_FALSE(isClosed(TriangleMesh{}));
  // An edge shared by three triangles is not closed either.
  TriangleMesh fin = makeCube(1.0f);
  fin.vertices.push_back({0.5f, 0.5f, 0.5f});
  fin.triangles.push_back({0, 1, 8});
  fin.triangles.push_back({1, 0, 8});
  EXPECT_FALSE(isClosed(fin));
}

void expectLoadError(const fs::path& file, const std::vector<std::string>& parts) {
  try {
    loadMesh(file);
    ADD_FAILURE() << "no error for " << file;
  } catch (const InputError& error) {
    const std::string message = error.what();
    for (const std::string& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
  }
}

TEST(MeshLoad, ObjErrorsNameFileAndLine) {
  ScratchDir dir;
  expectLoadError(dir.write("bad_vertex.obj", "v 0 0 0\nv 1 0 0\nv 1 x\n"),
                  {"bad_vertex.obj:3: expected 3 numbers after 'v', got 'v 1 x'"});
  expectLoadError(dir.write("short_vertex.obj", "# two numbers\nv 1 2\n"),
                  {"short_vertex.obj:2: expected 3 numbers after 'v'"});
  expectLoadError(dir.write("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 40\n"),
                  {"index.obj:5: face 2 refers to vertex 40 but the file has 3 vertices"});
  expectLoadError(dir.write("negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -5\n"),
                  {"negative.obj:4: face 1 refers to vertex -5 but only 3 vertices precede it"});
  expectLoadError(dir.write("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"),
                  {"two.obj:3: a face needs at least 3 vertices"});
  expectLoadError(dir.write("word.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 a 3\n"),
                  {"word.obj:4: expected vertex indices", "'f 1 a 3'"});
  expectLoadError(dir.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), {"zero.obj:4:"});
  expectLoadError(dir.write("points.obj", "v 0 0 0\nv 1 0 0\n"),
                  {"points.obj: the mesh has no triangles"});
  // A vertex at 3e38 once overflowed the sampler's lattice index.
  expectLoadError(dir.write("far.obj", "v 0 0 0\nv 3e38 0 0\nv 0 1 0\nf 1 2 3\n"),
                  {"far.obj: vertex 2 lies at", "farther than 1e6 from the origin"});
}

TEST(MeshLoad, StlErrorsNameFileAndLine) {
  ScratchDir dir;
  expectLoadError(dir.write("vertex.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n"),
                  {"vertex.stl:4: expected 3 numbers after 'vertex', got 'vertex 0 0'"});
  expectLoadError(dir.write("order.stl", "solid s\nfacet normal 0 0 1\nvertex 0 0 0\n"),
                  {"order.stl:3: expected 'outer loop' or 'endfacet', got 'vertex 0 0 0'"});
  expectLoadError(dir.write("cut.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"),
                  {"cut.stl: ends inside a facet"});
  expectLoadError(dir.write("empty.stl", "solid s\nendsolid s\n"),
                  {"empty.stl: the mesh has no triangles"});
  const std::string binary = cubeBinaryStl();
  // A truncated binary file whose header starts with "solid" is read as text and fails there.
  expectLoadError(dir.write("truncated.stl", binary.substr(0, binary.size() - 10)),
                  {"truncated.stl:1: binary data in an ASCII STL"});
  std::string noSolid = binary.substr(0, binary.size() - 10);
  noSolid.replace(0, 5, "cube ");
  expectLoadError(
      dir.write("nosolid.stl", noSolid),
      {"nosolid.stl: not an STL file", "counts 12 triangles, which take 684 bytes", "has 674"});
}

TEST(MeshLoad, RefusesOtherExtensionsAndMissingFiles) {
  ScratchDir dir;
  expectLoadError(dir.write("mesh.xyz", cubeObjWithQuads()),
                  {"mesh.xyz: not an OBJ or STL file (extension .xyz)"});
  expectLoadError(dir.write("mesh", cubeObjWithQuads()), {"(no extension)"});
  const fs::path absent = dir.path() / "absent.obj";
  expectLoadError(absent, {absent.string(), "does not exist"});
  // A pipe once blocked the read forever: refused without opening it.
  const fs::path pipe = dir.path() / "pipe.obj";
  ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
  expectLoadError(pipe, {pipe.string(), "is not a regular file"});
}

// Distance from p to the nearest sample, by brute force.
float nearestSampleDistance(const SampledPoints& samples, Vec3 p) {
  float best = std::numeric_limits<float>::infinity();
  for (const Vec3& q : samples.position) best = std::min(best, length(q - p));
  return best;
}

float minPairDistance(const SampledPoints& samples) {
  float best = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < samples.position.size(); ++i)
    for (std::size_t j = i + 1; j < samples.position.size(); ++j)
      best = std::min(best, length(samples.position[i] - samples.position[j]));
  return best;
}

TEST(MeshSurface, CubeSamplesLieOnFacesWithOutwardNormalsAndCoverThem) {
  const float side = 0.1f, spacing = 0.01f, onFace = 1e-5f;
  const SampledPoints samples = sampleMeshSurface(makeCube(side), spacing);
  ASSERT_EQ(samples.position.size(), samples.normal.size());
  // Six faces of 10 x 10 spacings: several hundred points, not thousands.
  EXPECT_GT(samples.position.size(), 500u);
  EXPECT_LT(samples.position.size(), 1200u);
  for (std::size_t i = 0; i < samples.position.size(); ++i) {
    const float p[3] = {samples.position[i].x, samples.position[i].y, samples.position[i].z};
    const float n[3] = {samples.normal[i].x, samples.normal[i].y, samples.normal[i].z};
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(p[a], -onFace);
      EXPECT_LE(p[a], side + onFace);
      if (std::abs(std::abs(n[a]) - 1.0f) < 1e-5f) axis = a;
    }
    ASSERT_NE(axis, -1) << "normal is not a face normal at sample " << i;
    EXPECT_NEAR(length(samples.normal[i]), 1.0f, 1e-5f);
    // Outward: the sample lies on the face the normal belongs to.
    const float faceAt = n[axis] > 0.0f ? side : 0.0f;
    EXPECT_NEAR(p[axis], faceAt, onFace) << "sample " << i;
  }
  EXPECT_GE(minPairDistance(samples), 0.45f * spacing);

  // Probes on every face, edges and corners included.
  float worst = 0.0f;
  const int probes = 40;
  for (int axis = 0; axis < 3; ++axis)
    for (float faceAt : {0.0f, side})
      for (int i = 0; i <= probes; ++i)
        for (int j = 0; j <= probes; ++j) {
          float q[3];
          q[axis] = faceAt;
          q[(axis + 1) % 3] = side * i / probes;
          q[(axis + 2) % 3] = side * j / probes;
          worst = std::max(worst, nearestSampleDistance(samples, Vec3{q[0], q[1], q[2]}));
        }
  EXPECT_LE(worst, 0.75f * spacing);
}

TEST(MeshSurface, IcosahedronSamplesCoverSlantedFacesAndSeams) {
  const TriangleMesh mesh = makeIcosahedron();
  ASSERT_EQ(mesh.triangles.size(), 20u);
  ASSERT_TRUE(isClosed(mesh));
  const float spacing = 0.1f;
  const SampledPoints samples = sampleMeshSurface(mesh, spacing);
  for (std::size_t i = 0; i < samples.position.size(); ++i) {
    const Vec3 p = samples.position[i], n = samples.normal[i];
    bool onItsTriangle = false;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const float plane = dot(p - mesh.vertices[mesh.triangles[t][0]], unitNormal(mesh, t));
      onItsTriangle =
          onItsTriangle || (length(n - unitNormal(mesh, t)) < 1e-5f && std::abs(plane) < 1e-5f);
    }
    EXPECT_TRUE(onItsTriangle) << "sample " << i;
    EXPECT_GT(dot(n, p), 0.0f);
  }
  EXPECT_GE(minPairDistance(samples), 0.45f * spacing);
  float worst = 0.0f;
  const int probes = 24;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i <= probes; ++i)
      for (int j = 0; i + j <= probes; ++j) {
        const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
        const Vec3 q = a + (b - a) * (float(i) / probes) + (c - a) * (float(j) / probes);
        worst = std::max(worst, nearestSampleDistance(samples, q));
      }
  EXPECT_LE(worst, 0.75f * spacing);
}

TEST(MeshSurface, IsDeterministic) {
  const TriangleMesh mesh = makeIcosahedron();
  const SampledPoints a = sampleMeshSurface(mesh, 0.2f), b = sampleMeshSurface(mesh, 0.2f);
  ASSERT_EQ(a.position.size(), b.position.size());
  EXPECT_EQ(std::memcmp(a.position.data(), b.position.data(), a.position.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.normal.data(), b.normal.data(), a.normal.size() * sizeof(Vec3)), 0);
}

TEST(MeshSolid, CubeFillsTheAlignedLattice) {
  const float side = 0.1f, spacing = 0.01f;
  const SampledPoints solid = sampleMeshSolid(makeCube(side), spacing);
  ASSERT_EQ(solid.position.size(), 1000u);
  ASSERT_EQ(solid.normal.size(), 1000u);
  for (std::size_t i = 0; i < solid.position.size(); ++i) {
    const float p[3] = {solid.position[i].x, solid.position[i].y, solid.position[i].z};
    const float n[3] = {solid.normal[i].x, solid.normal[i].y, solid.normal[i].z};
    float nearest = side;
    for (int a = 0; a < 3; ++a) {
      // On the lattice min + spacing / 2 + k spacing.
      const float k = (p[a] - 0.5f * spacing) / spacing;
      EXPECT_NEAR(k, std::round(k), 1e-4f);
      nearest = std::min({nearest, p[a], side - p[a]});
    }
    // The normal points at one of the nearest faces (several at equal distance are fine).
    bool towardNearestFace = false;
    for (int a = 0; a < 3; ++a) {
      const float toward = n[a] > 0.0f ? side - p[a] : p[a];
      towardNearestFace = towardNearestFace ||
                          (std::abs(std::abs(n[a]) - 1.0f) < 1e-5f && toward < nearest + 1e-6f);
    }
    EXPECT_TRUE(towardNearestFace) << "point " << i;
  }
}

TEST(MeshSolid, RaysThroughVerticesAndEdgesCountOnce) {
  // Lattice rows run exactly through the corners and along the edges of these octahedra.
  EXPECT_EQ(sampleMeshSolid(makeOctahedron(1.5f), 1.0f).position.size(), 7u);
  const float radius = 1.75f;
  const SampledPoints solid = sampleMeshSolid(makeOctahedron(radius), 0.5f);
  // Integer points with |a| + |b| + |c| <= 3.
  EXPECT_EQ(solid.position.size(), 63u);
  for (std::size_t i = 0; i < solid.position.size(); ++i) {
    const Vec3 p = solid.position[i], n = solid.normal[i];
    const float sum = std::abs(p.x) + std::abs(p.y) + std::abs(p.z);
    EXPECT_LT(sum, radius);
    EXPECT_NEAR(length(n), 1.0f, 1e-5f);
    // Walking the distance to the surface along the normal lands on the surface.
    const float depth = (radius - sum) / std::sqrt(3.0f);
    const Vec3 q = p + n * depth;
    EXPECT_NEAR(std::abs(q.x) + std::abs(q.y) + std::abs(q.z), radius, 1e-4f) << "point " << i;
  }
}

TEST(MeshSolid, RefusesOpenMeshes) {
  EXPECT_THROW(sampleMeshSolid(makeCube(1.0f, 5), 0.1f), InputError);
  EXPECT_THROW(sampleMeshSurface(makeCube(1.0f), 0.0f), InputError);
}

TEST(MeshContains, OctahedronIncludingTheAxesThroughCorners) {
  const TriangleMesh mesh = makeOctahedron(1.0f);
  ASSERT_TRUE(isClosed(mesh));
  for (const Vec3 p : {Vec3{0, 0, 0}, Vec3{0, 0, 0.9f}, Vec3{0, 0, -0.99f}, Vec3{0.9f, 0, 0},
                       Vec3{0, -0.5f, 0}, Vec3{0.3f, 0.3f, 0.3f}, Vec3{0.45f, 0.45f, 0}}) {
    EXPECT_TRUE(meshContains(mesh, p)) << p.x << " " << p.y << " " << p.z;
  }
  for (const Vec3 p : {Vec3{0, 0, 1.01f}, Vec3{0, 0, -3}, Vec3{2, 0, 0}, Vec3{-1.5f, 0, 0},
                       Vec3{0.4f, 0.4f, 0.4f}, Vec3{0.55f, 0.55f, 0}, Vec3{5, 5, 5}}) {
    EXPECT_FALSE(meshContains(mesh, p)) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(MeshContains, IcosahedronMatchesItsFacePlanes) {
  const TriangleMesh mesh = makeIcosahedron();
  // Along the axis through a corner: inside up to the corner, outside beyond.
  const Vec3 corner = mesh.vertices[0];
  for (float t : {0.0f, 0.3f, 0.9f, 0.999f, -0.999f}) EXPECT_TRUE(meshContains(mesh, corner * t));
  for (float t : {1.001f, 1.5f, -1.2f}) EXPECT_FALSE(meshContains(mesh, corner * t));
  // A grid of points against the half-spaces of the faces, away from the surface.
  int checked = 0;
  for (float x = -2.2f; x <= 2.2f; x += 0.23f)
    for (float y = -2.2f; y <= 2.2f; y += 0.23f)
      for (float z = -2.2f; z <= 2.2f; z += 0.23f) {
        const Vec3 p{x, y, z};
        float outside = -std::numeric_limits<float>::infinity();
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
          outside =
              std::max(outside, dot(p - mesh.vertices[mesh.triangles[t][0]], unitNormal(mesh, t)));
        }
        if (std::abs(outside) < 1e-3f) continue;
        EXPECT_EQ(meshContains(mesh, p), outside < 0.0f) << x << " " << y << " " << z;
        ++checked;
      }
  EXPECT_GT(checked, 5000);
}

}  // namespace
}  // namespace sph::objects
