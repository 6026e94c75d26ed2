// sph validate: read a scene, build it, and print what a run would use — without running it.
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "report.hpp"
#include "sph/scene_file.hpp"
#include "sph/simulation.hpp"

namespace sph::cli {

int validateCommand(const std::string& scenePath, const std::vector<std::string>& overrides) {
  const Scene scene = loadScene(scenePath, overrides);
  const Simulation sim(scene);
  printCalibration(stdout, sim);
  const FrameStats s = sim.stats();
  std::printf("  initial density      mean %.6g kg/m^3, max compression %.3g %%\n", s.meanDensity,
              100.0 * s.maxDensityError);
  std::printf("  outside the domain   %llu particles (removed before the first step)\n",
              static_cast<unsigned long long>(sim.removedCount()));
  std::string stages;
  for (const std::string& stage : sim.stageNames()) stages += (stages.empty() ? "" : ", ") + stage;
  std::printf("  a step               %s\n", stages.c_str());
  std::printf("%s: valid\n", scenePath.c_str());
  return kExitOk;
}

}  // namespace sph::cli
