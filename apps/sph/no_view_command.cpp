// sph view in a build without the viewer: says so.
#include <cstdio>

#include "commands.hpp"

namespace sph::cli {

bool viewerBuilt() {
  return false;
}

int viewCommand(const ViewCommandOptions&) {
  std::fprintf(stderr,
               "error: this build has no viewer (SPH_WITH_VIEWER=OFF, or GLFW or Dear ImGui "
               "missing: install libglfw3-dev and libimgui-dev, then reconfigure)\n");
  return kExitBadInput;
}

}  // namespace sph::cli
