// Any bytes as a run's object_surfaces.vtp, as sph render reads it back: the objects' surfaces
// or an InputError naming the file.
#include <cstddef>
#include <cstdint>
#include <string>

#include "sph/error.hpp"
#include "sph/io/object_surface_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    sph::io::parseObjectSurfaces(bytes, "object_surfaces.vtp");
  } catch (const sph::InputError&) {
  }
  return 0;
}
