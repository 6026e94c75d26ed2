// sph view: the interactive viewer (apps/view) on a scene file.
#include <cstdio>

#include "commands.hpp"
#include "sph/scene_file.hpp"
#include "sph/threads.hpp"
#include "viewer.hpp"

namespace sph::cli {

bool viewerBuilt() {
  return true;
}

int viewCommand(const ViewCommandOptions& options) {
  setThreadCount(options.threads);
  const Scene scene = loadScene(options.scene, options.overrides);
  view::ViewOptions view;
  view.simulation = simulationOptions(options.backend, options.device);
  view.width = options.width;
  view.height = options.height;
  view.colour = options.colour;
  view.look = options.look;
  view.objectSurfaces = options.objects != "particles";
  view.probe = !options.noProbe;
  view.frames = options.frames;
  view.screenshot = options.screenshot;
  view::runViewer(scene, view);  // no window: a std::runtime_error saying why, exit 1
  if (!options.screenshot.empty()) std::printf("screenshot: %s\n", options.screenshot.c_str());
  return kExitOk;
}

}  // namespace sph::cli
