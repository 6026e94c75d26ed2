// sph render in a build without the renderer: the command exists and says why it cannot run.
#include <cstdio>

#include "commands.hpp"

namespace sph::cli {

bool rendererBuilt() {
  return false;
}

int renderCommand(const RenderOptions&) {
  std::fprintf(stderr,
               "error: this build has no renderer (SPH_WITH_VIEWER=OFF): rebuild with "
               "-DSPH_WITH_VIEWER=ON (needs libepoxy-dev, libegl-dev and libpng-dev; "
               "docs/rendering.md)\n");
  return kExitBadInput;
}

}  // namespace sph::cli
