// Google Benchmark of a whole step on the box drop of Meteer 2011, with each stage's share as
// counters. `sph bench` prints the same measurement as a table; this one plugs into
// benchmark tooling (--benchmark_format=json, repetitions, comparisons).
#include <benchmark/benchmark.h>

#include "sph/box_drop_scene.hpp"
#include "sph/simulation.hpp"

namespace {

void BM_BoxDropStep(benchmark::State& state) {
  sph::Simulation sim(sph::boxDropScene(static_cast<int>(state.range(0))));
  for (int i = 0; i < 20; ++i) sim.step();  // leave the initial lattice
  sph::StepProfile sum;
  for (auto _ : state) {
    sim.step();
    const sph::StepProfile& p = sim.lastProfile();
    sum.buildGrid += p.buildGrid;
    sum.densityPressure += p.densityPressure;
    sum.forces += p.forces;
    sum.timeStep += p.timeStep;
    sum.integrate += p.integrate;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["grid_ms"] = sum.buildGrid / n;
  state.counters["density_ms"] = sum.densityPressure / n;
  state.counters["forces_ms"] = sum.forces / n;
  state.counters["dt_ms"] = sum.timeStep / n;
  state.counters["integrate_ms"] = sum.integrate / n;
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(sim.fluidCount()));
}
BENCHMARK(BM_BoxDropStep)->Arg(4096)->Arg(16384)->Arg(65536)->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
