// Any bytes as an OBJ or STL mesh (SPH_FUZZ_FILE names the format: "fuzz.obj", "fuzz.stl"): a
// mesh or an InputError naming the file; a mesh read is then checked for closure, sampled (at a
// spacing giving at most a few thousand points) and offset along its normals as walls and
// objects do.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "objects/mesh.hpp"
#include "sph/error.hpp"

namespace {

void exerciseMesh(const std::string& bytes, const char* name) {
  using namespace sph;
  objects::TriangleMesh mesh;
  try {
    mesh = objects::parseMesh(bytes, name);
  } catch (const InputError&) {
    return;
  }
  objects::isClosed(mesh);
  objects::signedVolume(mesh);
  if (mesh.triangles.size() > 2000) return;  // sampling cost grows with the mesh, not the bugs
  Vec3 lo = mesh.vertices.at(0), hi = lo;
  for (const Vec3& v : mesh.vertices) {
    lo = Vec3{std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = Vec3{std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  const float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(extent > 0.0f)) return;
  const float spacing = extent / 8.0f;
  try {
    objects::sampleMeshSurface(mesh, spacing);
    objects::sampleMeshSurface(objects::offsetAlongNormals(mesh, -0.5 * spacing), spacing);
    if (objects::isClosed(mesh)) objects::sampleMeshSolid(mesh, spacing);
  } catch (const InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  exerciseMesh(std::string(reinterpret_cast<const char*>(data), size), SPH_FUZZ_FILE);
  return 0;
}
