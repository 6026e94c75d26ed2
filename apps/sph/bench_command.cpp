// sph bench: the box drop of Meteer 2011 at the paper's particle counts, milliseconds per step
// by stage (median over the timed steps), and particle-steps per second.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "report.hpp"
#include "sph/box_drop_scene.hpp"
#include "sph/devices.hpp"
#include "sph/error.hpp"
#include "sph/scene_file.hpp"
#include "sph/simulation.hpp"
#include "sph/threads.hpp"

namespace sph::cli {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

struct StageSamples {
  std::vector<double> total, buildGrid, densityPressure, solve, forces, interaction, timeStep,
      integrate, objects;
  // The incompressible solver's iterations over the timed steps, and its errors.
  double densityIterations = 0.0, divergenceIterations = 0.0, densityError = 0.0;
  double largestDensityError = 0.0;
  void add(const StepProfile& p, const SolverStats& s) {
    total.push_back(p.total());
    buildGrid.push_back(p.buildGrid);
    densityPressure.push_back(p.densityPressure);
    solve.push_back(p.divergenceSolve + p.densitySolve);
    densityIterations += s.densityIterations;
    divergenceIterations += s.divergenceIterations;
    densityError += s.densityError;
    largestDensityError = std::max(largestDensityError, s.largestDensityError);
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
  if (scene.objectEngine.type == ObjectEngineKind::Bullet && !scene.objects.empty())
    throw InputError(scene.sourcePath +
                     ": object_engine.type: \"bullet\": its world steps outside the fluid's "
                     "stages, which this bench times; time it with sph run (its ms per step)");
  Simulation sim(scene, where);
  for (int i = 0; i < options.warmupSteps; ++i) sim.step();
  StageSamples samples;
  const double timedFrom = sim.time();
  for (int i = 0; i < options.steps; ++i) {
    sim.step();
    samples.add(sim.lastProfile(), sim.lastSolve());
  }
  const double step = median(samples.total);
  const double n = double(sim.fluidCount());
  const double rate = step > 0 ? n * 1000.0 / step : 0.0;
  const double interaction = median(samples.interaction);
  const double steps = double(options.steps);
  const double iterations = (samples.densityIterations + samples.divergenceIterations) / steps;
  const char* solver = scene.fluid.solver == FluidSolver::Dfsph ? "dfsph"
                       : scene.fluid.solver == FluidSolver::Pbf ? "pbf"
                                                                : "wcsph";
  // Simulated seconds per wall second, over the timed steps.
  const double simulatedPerStep = (sim.time() - timedFrom) / steps;
  const double realTime = step > 0 ? simulatedPerStep / (step / 1000.0) : 0.0;
  std::printf(
      "%-22s %-6s %10.0f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %6.1f %10.2e "
      "%9.4f\n",
      label.c_str(), solver, n, step, median(samples.buildGrid), median(samples.densityPressure),
      median(samples.solve), median(samples.forces), interaction, median(samples.timeStep),
      median(samples.integrate), median(samples.objects), iterations, simulatedPerStep, realTime);
  std::fflush(stdout);
  return {{"scene", label},
          {"solver", solver},
          {"particles", sim.fluidCount()},
          {"ms_per_step", step},
          {"build_grid_ms", median(samples.buildGrid)},
          {"density_pressure_ms", median(samples.densityPressure)},
          {"solve_ms", median(samples.solve)},
          {"density_iterations_per_step", samples.densityIterations / steps},
          {"divergence_iterations_per_step", samples.divergenceIterations / steps},
          {"average_density_error", samples.densityError / steps},
          {"largest_density_error", samples.largestDensityError},
          {"forces_ms", median(samples.forces)},
          {"interaction_ms", interaction},
          {"interaction_share", step > 0 ? interaction / step : 0.0},
          {"influence_ratio", scene.objects.empty() ? 0.0 : scene.interaction.influenceRatio},
          {"objects_ms", median(samples.objects)},
          {"time_step_ms", median(samples.timeStep)},
          {"integrate_ms", median(samples.integrate)},
          {"particle_steps_per_second", rate},
          {"simulated_seconds_per_step", simulatedPerStep},
          {"real_time_factor", realTime}};
}

}  // namespace

int benchCommand(const BenchOptions& options) {
  setThreadCount(options.threads);
  const SimulationOptions where = simulationOptions(options.backend, options.device);
  const bool gpu = where.backend == Backend::Cuda ||
                   (where.backend == Backend::Auto && !queryGpus().devices.empty());
  const char* backendName = gpu ? "cuda" : "cpu";
  std::printf(
      "sph bench: box drop, backend %s, %d threads, %d warm-up + %d timed steps; "
      "median ms per step\n",
      backendName, threadCount(), options.warmupSteps, options.steps);
  std::printf("%-22s %-6s %10s %9s %9s %9s %9s %9s %9s %9s %9s %9s %6s %10s %9s\n", "scene",
              "solver", "particles", "step", "grid", "density", "solve", "forces", "contacts", "dt",
              "integrate", "objects", "iters", "sim s/step", "real time");
  nlohmann::json results = nlohmann::json::array();
  // Each scene once with its own solver, or once with each solver asked for.
  const auto timeWithSolvers = [&](const std::string& label, Scene scene) {
    if (options.solvers.empty()) {
      results.push_back(timeScene(label, scene, where, options));
      return;
    }
    for (const std::string& solver : options.solvers) {
      scene.fluid.solver = solver == "dfsph" ? FluidSolver::Dfsph
                           : solver == "pbf" ? FluidSolver::Pbf
                                             : FluidSolver::Wcsph;
      // The position solver couples objects only as boundary particles, the weakly
      // compressible one only by contact.
      if (!scene.objects.empty() && scene.fluid.solver != FluidSolver::Dfsph)
        scene.interaction.coupling = scene.fluid.solver == FluidSolver::Pbf
                                         ? ObjectCoupling::Boundary
                                         : ObjectCoupling::Contact;
      results.push_back(timeScene(label, scene, where, options));
    }
  };
  for (int size : options.sizes) timeWithSolvers("box_drop", boxDropScene(size));
  for (const std::string& path : options.scenes) {
    Scene scene = loadScene(path, options.overrides);
    if (scene.objects.empty() || options.influenceRatios.empty()) {
      timeWithSolvers(scene.name, scene);
      continue;
    }
    for (double ratio : options.influenceRatios) {
      scene.interaction.influenceRatio = ratio;
      char label[64];
      std::snprintf(label, sizeof label, "%s r%.2g", scene.name.c_str(), ratio);
      timeWithSolvers(label, scene);
    }
  }
  if (!options.json.empty()) {
    // JSON Lines: one object per scene and size, each saying where it ran.
    std::ofstream out(options.json);
    for (nlohmann::json& result : results) {
      result["backend"] = backendName;
      result["threads"] = threadCount();
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
