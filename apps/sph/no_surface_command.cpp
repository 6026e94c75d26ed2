// sph surface in a build without OpenVDB: the command exists and says why it cannot run.
#include <cstdio>

#include "commands.hpp"

namespace sph::cli {

bool surfaceBuilt() {
  return false;
}

int surfaceCommand(const SurfaceOptions&) {
  std::fprintf(stderr,
               "error: this build has no surface meshes (SPH_WITH_OPENVDB=OFF or OpenVDB not "
               "found): rebuild with -DSPH_WITH_OPENVDB=ON (needs libopenvdb-dev; "
               "docs/rendering.md)\n");
  return kExitBadInput;
}

}  // namespace sph::cli
