// Google Benchmarks of each stage of a step alone, on the CPU backend: the box drop
// (Meteer 2011, §10) after 20 steps, at the paper's particle counts. Each stage is called as
// Simulation::step calls it, through the engine, and is valid to repeat on its own: building the
// grid of particles already in cell order, recomputing density, pressure and forces from the
// same positions, reducing the same measures, integrating with a step too small to move
// anything.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "sim/calibration.hpp"
#include "sim/fluid_engine.hpp"
#include "sph/box_drop_scene.hpp"
#include "sph/simulation.hpp"

namespace {

using sph::sim::FluidEngine;

constexpr int kStepsBefore = 20;  // leave the initial lattice, as BM_BoxDropStep does

// The box drop's fluid after kStepsBefore steps of a Simulation, by id.
struct SteppedBoxDrop {
  sph::Scene scene;
  sph::Calibration calibration;
  std::vector<sph::Vec3> position;  // m
  std::vector<sph::Vec3> velocity;  // m/s
  double dt = 0.0;                  // s, the last step's
};

sph::Vec3 vec3At(const std::vector<float>& xyz, std::size_t i) {
  return sph::Vec3{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
}

SteppedBoxDrop stepBoxDrop(int particles) {
  SteppedBoxDrop s;
  s.scene = sph::boxDropScene(particles);
  sph::Simulation sim(s.scene);
  for (int i = 0; i < kStepsBefore; ++i) sim.step();
  s.calibration = sim.calibration();
  s.dt = sim.lastDt();
  const sph::ParticleFrame frame = sim.frame(false);  // the box drop has fluid alone
  for (std::size_t i = 0; i < frame.size(); ++i) {
    s.position.push_back(vec3At(frame.position, i));
    s.velocity.push_back(vec3At(frame.velocity, i));
  }
  return s;
}

// Google Benchmark calls each benchmark more than once; the steps are taken once per size.
const SteppedBoxDrop& steppedBoxDrop(int particles) {
  static std::map<int, SteppedBoxDrop> stepped;
  auto found = stepped.find(particles);
  if (found == stepped.end()) found = stepped.emplace(particles, stepBoxDrop(particles)).first;
  return found->second;
}

// A CPU engine holding that state, with the stages before the one timed already run: each
// stage's inputs are there, as in a step.
std::unique_ptr<FluidEngine> engineAfterSteps(benchmark::State& state) {
  const SteppedBoxDrop& s = steppedBoxDrop(static_cast<int>(state.range(0)));
  sph::sim::EngineSetup setup =
      sph::sim::engineSetup(s.scene, s.calibration, sph::sim::Walls(s.scene));
  setup.positions = s.position;
  setup.velocities = s.velocity;
  std::unique_ptr<FluidEngine> engine = sph::sim::makeCpuEngine(setup);
  engine->buildGrid();
  engine->computeDensityAndPressure();
  engine->computeForces();
  return engine;
}

void countParticles(benchmark::State& state, const FluidEngine& engine) {
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(engine.fluidCount()));
}

void BM_BuildGrid(benchmark::State& state) {
  const std::unique_ptr<FluidEngine> engine = engineAfterSteps(state);
  for (auto _ : state) benchmark::DoNotOptimize(engine->buildGrid());
  countParticles(state, *engine);
}

void BM_DensityPressure(benchmark::State& state) {
  const std::unique_ptr<FluidEngine> engine = engineAfterSteps(state);
  for (auto _ : state) engine->computeDensityAndPressure();
  countParticles(state, *engine);
}

void BM_Forces(benchmark::State& state) {
  const std::unique_ptr<FluidEngine> engine = engineAfterSteps(state);
  for (auto _ : state) engine->computeForces();
  countParticles(state, *engine);
}

// The reduction the time step is chosen from (the "dt" column of sph bench, less the few
// scalar operations that follow it).
void BM_MeasureStep(benchmark::State& state) {
  const std::unique_ptr<FluidEngine> engine = engineAfterSteps(state);
  for (auto _ : state) benchmark::DoNotOptimize(engine->measureStep());
  countParticles(state, *engine);
}

void BM_Integrate(benchmark::State& state) {
  const std::unique_ptr<FluidEngine> engine = engineAfterSteps(state);
  // A millionth of the last step: the state stays that of the box drop however many times the
  // step is repeated, and the work per particle is the same for any dt.
  const float dt = static_cast<float>(1e-6 * steppedBoxDrop(static_cast<int>(state.range(0))).dt);
  for (auto _ : state) benchmark::DoNotOptimize(engine->integrate(dt));
  countParticles(state, *engine);
}

// The paper's particle counts (16 Ki, 64 Ki, 256 Ki), in wall-clock time: the stages run on
// every OpenMP thread.
void paperSizes(benchmark::internal::Benchmark* b) {
  b->Arg(16384)->Arg(65536)->Arg(262144)->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK(BM_BuildGrid)->Apply(paperSizes);
BENCHMARK(BM_DensityPressure)->Apply(paperSizes);
BENCHMARK(BM_Forces)->Apply(paperSizes);
BENCHMARK(BM_MeasureStep)->Apply(paperSizes);
BENCHMARK(BM_Integrate)->Apply(paperSizes);

}  // namespace

BENCHMARK_MAIN();
