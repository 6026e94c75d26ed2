// sph bench: the seed's box drop at the paper's particle counts, milliseconds per step by
// stage (median over the timed steps), and particle-steps per second.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "backend/cpu_parallel.hpp"
#include "commands.hpp"
#include "report.hpp"
#include "sph/box_drop_scene.hpp"
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
  std::vector<double> total, buildGrid, densityPressure, forces, timeStep, integrate;
  void add(const StepProfile& p) {
    total.push_back(p.total());
    buildGrid.push_back(p.buildGrid);
    densityPressure.push_back(p.densityPressure);
    forces.push_back(p.forces);
    timeStep.push_back(p.timeStep);
    integrate.push_back(p.integrate);
  }
};

}  // namespace

int benchCommand(const BenchOptions& options) {
  if (!checkBackend(options.backend)) return kExitBadInput;
  backend::setThreadCount(options.threads);
  std::printf(
      "sph bench: box drop, backend %s, %d threads, %d warm-up + %d timed steps; "
      "median ms per step\n",
      backendName(), backend::threadCount(), options.warmupSteps, options.steps);
  std::printf("%10s %9s %9s %9s %9s %9s %9s %14s\n", "particles", "step", "grid", "density",
              "forces", "dt", "integrate", "particle-steps/s");
  nlohmann::json results = nlohmann::json::array();
  for (int size : options.sizes) {
    Simulation sim(boxDropScene(size));
    for (int i = 0; i < options.warmupSteps; ++i) sim.step();
    StageSamples samples;
    for (int i = 0; i < options.steps; ++i) {
      sim.step();
      samples.add(sim.lastProfile());
    }
    const double step = median(samples.total);
    const double n = double(sim.fluidCount());
    const double rate = step > 0 ? n * 1000.0 / step : 0.0;
    std::printf("%10.0f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %14.3e\n", n, step,
                median(samples.buildGrid), median(samples.densityPressure), median(samples.forces),
                median(samples.timeStep), median(samples.integrate), rate);
    std::fflush(stdout);
    results.push_back({{"particles", sim.fluidCount()},
                       {"ms_per_step", step},
                       {"build_grid_ms", median(samples.buildGrid)},
                       {"density_pressure_ms", median(samples.densityPressure)},
                       {"forces_ms", median(samples.forces)},
                       {"time_step_ms", median(samples.timeStep)},
                       {"integrate_ms", median(samples.integrate)},
                       {"particle_steps_per_second", rate}});
  }
  if (!options.json.empty()) {
    std::ofstream out(options.json);
    out << nlohmann::json{{"backend", backendName()},
                          {"threads", backend::threadCount()},
                          {"scene", "box_drop"},
                          {"results", results}}
               .dump(2)
        << '\n';
    if (!out) {
      std::fprintf(stderr, "error: %s: cannot write the results\n", options.json.c_str());
      return 1;
    }
  }
  return kExitOk;
}

}  // namespace sph::cli
