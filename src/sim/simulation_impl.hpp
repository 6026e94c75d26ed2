// The state behind sph::Simulation, shared by the files that implement it.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "sim/calibration.hpp"
#include "sim/fluid_engine.hpp"
#include "sim/sampling.hpp"
#include "sph/core/kernels.hpp"
#include "sph/core/time_step.hpp"
#include "sph/devices.hpp"
#include "sph/error.hpp"
#include "sph/simulation.hpp"

namespace sph {

namespace detail {

template <class Stage>
inline double timedMs(Stage&& stage) {
  const auto start = std::chrono::steady_clock::now();
  stage();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace detail

struct Simulation::Impl {
  Scene scene;
  Calibration calibration;
  fluid::FluidParameters params;
  std::unique_ptr<sim::FluidEngine> engine;
  StepProfile profile;
  double time = 0.0;
  double dt = 0.0;
  std::uint64_t steps = 0;
  std::uint64_t removed = 0;
  std::uint64_t clamped = 0;
  std::uint64_t initialFluid = 0;

  Impl(const Scene& s, const SimulationOptions& options) : scene(s) {
    calibration = sim::calibrate(scene);
    params = sim::fluidParameters(scene, calibration);
    dt = calibration.initialDt;

    sim::EngineSetup setup;
    setup.params = params;
    setup.domain = sim::domainParameters(scene);
    sampleFluid(setup);
    for (const auto& tank : scene.walls) {
      const auto points = sim::sampleTank(tank, scene.fluid.spacing, scene.gravity);
      setup.walls.insert(setup.walls.end(), points.begin(), points.end());
    }
    // Twice the neighbours of a particle in the initial lattice leaves room for compression.
    const double ratio = scene.fluid.supportRatio;
    setup.neighborStride =
        static_cast<std::uint32_t>(std::ceil(2.0 * 4.0 / 3.0 * kPi * ratio * ratio * ratio));
    initialFluid = setup.positions.size();
    engine =
        useCuda(options) ? sim::makeCudaEngine(setup, options.device) : sim::makeCpuEngine(setup);

    calibration.fluidParticles = initialFluid;
    calibration.boundaryParticles = engine->wallCount();
    // Density and pressure of the initial state, so stats and frame 0 are meaningful.
    removed += engine->buildGrid();
    engine->computeDensityAndPressure();
  }

  static bool useCuda(const SimulationOptions& options) {
    if (options.backend == Backend::Cuda) return true;
    return options.backend == Backend::Auto && !queryGpus().devices.empty();
  }

  void sampleFluid(sim::EngineSetup& setup) const {
    for (const auto& block : scene.fluid.blocks) {
      auto points = sim::sampleBlock(block.box, scene.fluid.spacing);
      if (block.hydrostatic)
        sim::compressHydrostatically(points, block.box, scene.gravity, calibration.soundSpeed);
      const Vec3 v{float(block.velocity[0]), float(block.velocity[1]), float(block.velocity[2])};
      setup.positions.insert(setup.positions.end(), points.begin(), points.end());
      setup.velocities.insert(setup.velocities.end(), points.size(), v);
    }
  }

  double chooseTimeStep(double until) {
    const fluid::StepMeasures m = engine->measureStep();
    const float bound = static_cast<float>(scene.failure.maxDensityError);
    if (!m.finite || m.maxDensityError > bound) fail(bound);
    const TimeDesc& t = scene.time;
    double next =
        t.fixedDt
            ? *t.fixedDt
            : std::min({cflTimeStep(t.cfl, params.h, params.soundSpeed, m.maxSpeed),
                        forceTimeStep(t.forceFactor, params.h, m.maxAcceleration),
                        viscousTimeStep(t.viscousFactor, params.h, calibration.kinematicViscosity),
                        t.maxDt});
    const double remaining = until - time;
    // Land exactly on `until` rather than leave a sliver of a step for later.
    if (next >= remaining)
      next = remaining;
    else if (next > 0.5 * remaining)
      next = 0.5 * remaining;
    return next;
  }

  [[noreturn]] void fail(float bound) {
    const fluid::BadParticle bad = engine->findBadParticle(bound);
    std::ostringstream message;
    message << "simulation failed at step " << steps << " (t = " << time << " s): particle "
            << bad.id << ": " << bad.quantity << " = " << bad.value;
    if (bad.pastBound) message << ", past failure.max_density_error = " << bound;
    throw SimulationFailure(message.str(), steps, bad.id, bad.quantity);
  }
};

}  // namespace sph
