#include "mesh_files.hpp"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <system_error>

#include "sph/error.hpp"

namespace sph::surface {

namespace {

void writeVtp(std::ostream& out, const TriangleMesh& mesh) {
  out.precision(9);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      << "<PolyData>\n<Piece NumberOfPoints=\"" << mesh.vertexCount() << "\" NumberOfPolys=\""
      << mesh.triangleCount() << "\">\n"
      << "<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    out << mesh.vertices[i] << ((i % 3 == 2) ? '\n' : ' ');
  out << "</DataArray>\n</Points>\n<Polys>\n"
      << "<DataArray type=\"UInt32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    out << mesh.triangles[i] << ((i % 3 == 2) ? '\n' : ' ');
  out << "</DataArray>\n<DataArray type=\"UInt32\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t t = 1; t <= mesh.triangleCount(); ++t) out << 3 * t << '\n';
  out << "</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

void writeObj(std::ostream& out, const TriangleMesh& mesh) {
  out.precision(9);
  out << "# the fluid's surface, written by sph surface\n";
  for (std::size_t i = 0; i < mesh.vertices.size(); i += 3)
    out << "v " << mesh.vertices[i] << ' ' << mesh.vertices[i + 1] << ' ' << mesh.vertices[i + 2]
        << '\n';
  for (std::size_t i = 0; i < mesh.triangles.size(); i += 3)  // OBJ counts from 1
    out << "f " << mesh.triangles[i] + 1 << ' ' << mesh.triangles[i + 1] + 1 << ' '
        << mesh.triangles[i + 2] + 1 << '\n';
}

void writePly(std::ostream& out, const TriangleMesh& mesh) {
  out << "ply\nformat binary_little_endian 1.0\ncomment the fluid's surface, written by sph\n"
      << "element vertex " << mesh.vertexCount() << "\nproperty float x\nproperty float y\n"
      << "property float z\nelement face " << mesh.triangleCount()
      << "\nproperty list uchar uint vertex_indices\nend_header\n";
  out.write(reinterpret_cast<const char*>(mesh.vertices.data()),
            std::streamsize(mesh.vertices.size() * sizeof(float)));
  const std::uint8_t three = 3;
  for (std::size_t i = 0; i < mesh.triangles.size(); i += 3) {
    out.write(reinterpret_cast<const char*>(&three), 1);
    out.write(reinterpret_cast<const char*>(&mesh.triangles[i]), 3 * sizeof(std::uint32_t));
  }
}

}  // namespace

const char* extensionOf(MeshFormat format) {
  switch (format) {
    case MeshFormat::Obj:
      return "obj";
    case MeshFormat::Ply:
      return "ply";
    default:
      return "vtp";
  }
}

void writeMesh(const std::filesystem::path& path, const TriangleMesh& mesh, MeshFormat format) {
  std::filesystem::path partial = path;
  partial += ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    if (!out) throw OutputError(path.string() + ": cannot open for writing");
    if (format == MeshFormat::Vtp)
      writeVtp(out, mesh);
    else if (format == MeshFormat::Obj)
      writeObj(out, mesh);
    else
      writePly(out, mesh);
    out.flush();
    if (!out) throw OutputError(path.string() + ": write failed (disk full?)");
  }
  std::error_code error;
  std::filesystem::rename(partial, path, error);
  if (error) throw OutputError(path.string() + ": cannot rename into place: " + error.message());
}

}  // namespace sph::surface
