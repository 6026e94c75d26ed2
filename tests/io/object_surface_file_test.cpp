// The objects' drawn surfaces written to object_surfaces.vtp read back identical; damaged files
// give errors that name the file.
#include "sph/io/object_surface_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sph/error.hpp"

namespace sph::io {
namespace {

namespace fs = std::filesystem;

// Two objects: a tetrahedron (object 1) and a single triangle (object 4).
std::vector<ObjectSurfaceMesh> twoSurfaces() {
  ObjectSurfaceMesh a;
  a.object = 1;
  a.restPosition = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  a.triangles = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  a.anchor = {10, 11, 12, 11, 12, 13, 12, 13, 10, 13, 10, 11};
  a.coordinate = {0, 0, 0, 0.5f, 0.25f, -0.001f, 0, 0, 0.003f, 1, 0, 0};
  ObjectSurfaceMesh b;
  b.object = 4;
  b.restPosition = {2, 2, 2, 3, 2, 2, 2, 3, 2};
  b.triangles = {0, 1, 2};
  b.anchor = {20, 21, 22, 21, 22, 20, 22, 20, 21};
  b.coordinate = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f};
  return {a, b};
}

class ObjectSurfaceFileTest : public testing::Test {
 protected:
  void SetUp() override {
    file_ = fs::temp_directory_path() /
            ("sph_object_surfaces_" + std::to_string(::getpid()) + "_" +
             testing::UnitTest::GetInstance()->current_test_info()->name() + ".vtp");
  }
  void TearDown() override { fs::remove(file_); }
  std::string bytes() const {
    std::ifstream in(file_, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  void expectError(const std::string& bytes, const std::string& what) const {
    try {
      parseObjectSurfaces(bytes, file_);
      FAIL() << "read without error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(file_.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
  fs::path file_;
};

TEST_F(ObjectSurfaceFileTest, RoundTripsEverySurface) {
  const std::vector<ObjectSurfaceMesh> written = twoSurfaces();
  writeObjectSurfaces(written, file_);
  const std::vector<ObjectSurfaceMesh> read = readObjectSurfaces(file_);
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t s = 0; s < read.size(); ++s) {
    EXPECT_EQ(read[s].object, written[s].object);
    EXPECT_EQ(read[s].restPosition, written[s].restPosition);
    EXPECT_EQ(read[s].triangles, written[s].triangles);
    EXPECT_EQ(read[s].anchor, written[s].anchor);
    EXPECT_EQ(read[s].coordinate, written[s].coordinate);
  }
  // ParaView reads the triangles as polygons of the points.
  EXPECT_NE(bytes().find("NumberOfPoints=\"7\""), std::string::npos);
  EXPECT_NE(bytes().find("NumberOfPolys=\"5\""), std::string::npos);
}

TEST_F(ObjectSurfaceFileTest, DamagedFilesNameTheFile) {
  writeObjectSurfaces(twoSurfaces(), file_);
  const std::string good = bytes();
  expectError(good.substr(0, good.size() - 40), "truncated");
  std::string renamed = good;
  renamed.replace(renamed.find("Name=\"anchor\""), 13, "Name=\"anchors\"");
  expectError(renamed, "no DataArray named 'anchor'");
  expectError("solid cube\n", "not a VTK XML PolyData file");
}

TEST_F(ObjectSurfaceFileTest, ATriangleAcrossTwoObjectsIsRefused) {
  std::vector<ObjectSurfaceMesh> surfaces = twoSurfaces();
  surfaces[1].triangles = {0, 1, 2};
  writeObjectSurfaces(surfaces, file_);
  std::string damaged = bytes();
  // The last triangle's first vertex (4 + 0) moved to the first object's vertex 0.
  const std::size_t polys = damaged.find("Name=\"connectivity\"");
  ASSERT_NE(polys, std::string::npos);
  const std::size_t at = damaged.find("offset=\"", polys) + 8;
  const std::size_t offset = std::stoull(damaged.substr(at));
  const std::size_t data = damaged.find('_', damaged.find("<AppendedData")) + 1;
  const std::size_t lastTriangle = data + offset + 8 + 4 * 3 * sizeof(std::int64_t);
  const std::int64_t vertex = 0;
  damaged.replace(lastTriangle, sizeof vertex, reinterpret_cast<const char*>(&vertex),
                  sizeof vertex);
  expectError(damaged, "expected one of its object's vertices");
}

TEST_F(ObjectSurfaceFileTest, AnUnwritableFileIsAnOutputError) {
  EXPECT_THROW(writeObjectSurfaces(twoSurfaces(), "/nonexistent/dir/object_surfaces.vtp"),
               OutputError);
}

}  // namespace
}  // namespace sph::io
