#include "particle_surface.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <mutex>
#include <stdexcept>

namespace sph::surface {

namespace {

// What ParticlesToLevelSet reads: positions and one radius for all.
class ParticleList {
 public:
  using PosType = openvdb::Vec3R;
  ParticleList(const std::vector<float>& points, double radius)
      : points_(points), radius_(radius) {}
  std::size_t size() const { return points_.size() / 3; }
  void getPos(std::size_t n, openvdb::Vec3R& xyz) const {
    xyz = openvdb::Vec3R(points_[3 * n], points_[3 * n + 1], points_[3 * n + 2]);
  }
  void getPosRad(std::size_t n, openvdb::Vec3R& xyz, openvdb::Real& radius) const {
    getPos(n, xyz);
    radius = radius_;
  }

 private:
  const std::vector<float>& points_;
  double radius_;
};

// How far the union of the spheres is moved in, in spacings: to where the fluid ends, half a
// spacing past its outer particles, less the union's mean dip between neighbouring spheres on
// a lattice's face (about a tenth of a spacing), which the smoothing fills in.
constexpr double kInward = 0.4;

// The narrow band's half width, in voxels: room for the move in.
constexpr float kHalfWidth = 4.0f;

void initialiseOnce() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

}  // namespace

TriangleMesh reconstructSurface(const std::vector<float>& points, const SurfaceSettings& s) {
  if (!(s.spacing > 0.0) || !(s.voxel > 0.0))
    throw std::invalid_argument("reconstructSurface: the spacing and the voxel must be positive");
  TriangleMesh mesh;
  if (points.empty()) return mesh;
  initialiseOnce();
  const double voxel = s.voxel * s.spacing;
  openvdb::FloatGrid::Ptr grid = openvdb::createLevelSet<openvdb::FloatGrid>(voxel, kHalfWidth);
  {
    openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
    raster.setRmin(0.0);  // small voxels or not, every particle counts
    raster.rasterizeSpheres(ParticleList(points, s.spacing));
    raster.finalize(/*prune=*/true);
  }
  openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*grid);
  for (int k = 0; k < s.smoothing; ++k) filter.meanCurvature();
  filter.offset(kInward * s.spacing);

  std::vector<openvdb::Vec3s> vertices;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, vertices, triangles, quads, 0.0, 0.0);
  mesh.vertices.reserve(3 * vertices.size());
  for (const openvdb::Vec3s& v : vertices)
    mesh.vertices.insert(mesh.vertices.end(), {v.x(), v.y(), v.z()});
  // OpenVDB winds its faces clockwise seen from outside: reversed here.
  mesh.triangles.reserve(3 * (triangles.size() + 2 * quads.size()));
  for (const openvdb::Vec3I& t : triangles)
    mesh.triangles.insert(mesh.triangles.end(), {t[2], t[1], t[0]});
  for (const openvdb::Vec4I& q : quads) {
    mesh.triangles.insert(mesh.triangles.end(), {q[2], q[1], q[0]});
    mesh.triangles.insert(mesh.triangles.end(), {q[3], q[2], q[0]});
  }
  return mesh;
}

}  // namespace sph::surface
