// The objects' drawn surfaces (sph/object_surface.hpp) as one VTK XML PolyData file: the surfaces
// as built (Points, and triangles as Polys) with, per vertex, its object (Int32), the ids of the
// three particles it hangs on (`anchor`, UInt32 × 3) and its coordinates on them
// (`coordinate`, Float32 × 3). `sph run` writes DIR/object_surfaces.vtp once; ParaView opens it
// as the objects' rest shapes, `sph render` draws each frame's objects through it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sph/object_surface.hpp"

namespace sph::io {

// Atomically, as the frames are. Throws OutputError naming the path when it cannot be written.
void writeObjectSurfaces(const std::vector<ObjectSurfaceMesh>& surfaces,
                         const std::filesystem::path& file);

// Throws InputError naming the file and what was expected when it cannot be read.
std::vector<ObjectSurfaceMesh> readObjectSurfaces(const std::filesystem::path& file);
std::vector<ObjectSurfaceMesh> parseObjectSurfaces(const std::string& bytes,
                                                   const std::filesystem::path& file);

}  // namespace sph::io
