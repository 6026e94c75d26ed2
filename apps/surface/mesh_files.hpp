// A surface mesh written for other tools: VTK PolyData (.vtp, ParaView), Wavefront OBJ
// (Blender and most modellers) or binary PLY.
#pragma once

#include <filesystem>
#include <string>

#include "triangle_mesh.hpp"

namespace sph::surface {

enum class MeshFormat { Vtp, Obj, Ply };

// "vtp", "obj", "ply"
const char* extensionOf(MeshFormat format);

// Writes through a temporary file renamed into place, so that a reader never sees half a mesh.
// Throws OutputError naming the path when it cannot be written.
void writeMesh(const std::filesystem::path& path, const TriangleMesh& mesh, MeshFormat format);

}  // namespace sph::surface
