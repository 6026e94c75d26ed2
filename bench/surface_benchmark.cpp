// The fluid's surface mesh of one frame (apps/surface): the dam break's column of 67,626
// particles (0.2 m × 0.2 m × 0.1 m at a spacing of 3.9 mm), from particles to a closed mesh,
// at the default settings.
#include <benchmark/benchmark.h>

#include <vector>

#include "particle_surface.hpp"

namespace {

void BM_DamBreakColumnSurface(benchmark::State& state) {
  const double spacing = 0.0039;
  std::vector<float> points;
  for (int i = 0; i < 51; ++i)
    for (int j = 0; j < 51; ++j)
      for (int k = 0; k < 26; ++k)
        points.insert(points.end(), {float((i + 0.5) * spacing), float((j + 0.5) * spacing),
                                     float((k + 0.5) * spacing)});
  sph::surface::SurfaceSettings settings;
  settings.spacing = spacing;
  std::size_t triangles = 0;
  for (auto _ : state) {
    const sph::surface::TriangleMesh mesh = sph::surface::reconstructSurface(points, settings);
    triangles = mesh.triangleCount();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["particles"] = double(points.size() / 3);
  state.counters["triangles"] = double(triangles);
}
BENCHMARK(BM_DamBreakColumnSurface)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
