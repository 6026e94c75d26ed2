// sph bench: the seed's box drop at the paper's particle counts, milliseconds per step by
// stage (median over the timed steps), and particle-steps per second.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "backend/cpu_parallel.hpp"
#include "commands.hpp"
#include "io/scene_loader.hpp"
#include "report.hpp"
#include "sph/box_drop_scene.hpp"
#include "sph/devices.hpp"
#include "sph/simulation.hpp"

namespace sph::cli {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

struct StageSamples {
  std::vector<double> total, buildGrid, densityPressure, forces, interaction, timeStep, integrate,
      objects;
  void add(const StepProfile& p) {
    total.push_back(p.total());
    buildGrid.push_back(p.buildGrid);
    densityPressure.push_back(p.densityPressure);
    forces.push_back(p.forces);
    interaction.push_back(p.interaction);
    timeStep.push_back(p.timeStep);
    integrate.push_back(p.integrate);
    objects.push_back(p.objects);
  }
};

// Times `steps` steps after `warmup`; one row of the table.
nlohmann::json timeScene(const std::string& label, const Scene& scene,
                         const SimulationOptions& where, const BenchOptions& options) {
  Simulation sim(scene, where);
  for (int i = 0; i < options.warmupSteps; ++i) sim.step();
  StageSamples samples;
  for (int i = 0; i < options.steps; ++i) {
    sim.step();
    samples.add(sim.lastProfile());
  }
  const double step = median(samples.total);
  const double n = double(sim.fluidCount());
  const double rate = step > 0 ? n * 1000.0 / step : 0.0;
  const double interaction = median(samples.interaction);
  std::printf("%-22s %10.0f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %14.3e\n",
              label.c_str(), n, step, median(samples.buildGrid), median(samples.densityPressure),
              median(samples.forces), interaction, median(samples.timeStep),
              median(samples.integrate), median(samples.objects), rate);
  std::fflush(stdout);
  return {{"scene", label},
          {"particles", sim.fluidCount()},
          {"ms_per_step", step},
          {"build_grid_ms", median(samples.buildGrid)},
          {"density_pressure_ms", median(samples.densityPressure)},
          {"forces_ms", median(samples.forces)},
          {"interaction_ms", interaction},
          {"interaction_share", step > 0 ? interaction / step : 0.0},
          {"influence_ratio", scene.objects.empty() ? 0.0 : scene.interaction.influenceRatio},
          {"objects_ms", median(samples.objects)},
          {"time_step_ms", median(samples.timeStep)},
          {"integrate_ms", median(samples.integrate)},
          {"particle_steps_per_second", rate},
          {"simulated_seconds_per_step", sim.time() / double(sim.stepCount())},
          // Simulated seconds per wall second over the timed steps' median.
          {"real_time_factor", sim.time() / double(sim.stepCount()) / (step / 1000.0)}};
}

}  // namespace

int benchCommand(const BenchOptions& options) {
  backend::setThreadCount(options.threads);
  const SimulationOptions where = simulationOptions(options.backend, options.device);
  const bool gpu = where.backend == Backend::Cuda ||
                   (where.backend == Backend::Auto && !queryGpus().devices.empty());
  const char* backendName = gpu ? "cuda" : "cpu";
  std::printf(
      "sph bench: box drop, backend %s, %d threads, %d warm-up + %d timed steps; "
      "median ms per step\n",
      backendName, backend::threadCount(), options.warmupSteps, options.steps);
  std::printf("%-22s %10s %9s %9s %9s %9s %9s %9s %9s %9s %14s\n", "scene", "particles", "step",
              "grid", "density", "forces", "contacts", "dt", "integrate", "objects",
              "particle-steps/s");
  nlohmann::json results = nlohmann::json::array();
  for (int size : options.sizes)
    results.push_back(timeScene("box_drop", boxDropScene(size), where, options));
  for (const std::string& path : options.scenes) {
    Scene scene = io::loadScene(path, options.overrides);
    if (scene.objects.empty() || options.influenceRatios.empty()) {
      results.push_back(timeScene(scene.name, scene, where, options));
      continue;
    }
    for (double ratio : options.influenceRatios) {
      scene.interaction.influenceRatio = ratio;
      char label[64];
      std::snprintf(label, sizeof label, "%s r%.2g", scene.name.c_str(), ratio);
      results.push_back(timeScene(label, scene, where, options));
    }
  }
  if (!options.json.empty()) {
    // JSON Lines: one object per scene and size, each saying where it ran.
    std::ofstream out(options.json);
    for (nlohmann::json& result : results) {
      result["backend"] = backendName;
      result["threads"] = backend::threadCount();
      result["batched_passes"] = !gpu && where.cpuPasses == CpuPasses::Batched;
      out << result.dump() << '\n';
    }
    if (!out) {
      std::fprintf(stderr, "error: %s: cannot write the results\n", options.json.c_str());
      return 1;
    }
  }
  return kExitOk;
}

}  // namespace sph::cli
