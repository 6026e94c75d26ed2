// The state behind sph::Simulation, shared by the files that implement it.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "fluid/stages.hpp"
#include "sim/calibration.hpp"
#include "sim/sampling.hpp"
#include "sph/core/kernels.hpp"
#include "sph/core/time_step.hpp"
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
  fluid::DomainParameters domain;
  fluid::FluidParticles fluid;
  fluid::BoundaryParticles boundary;
  fluid::Grid grid;
  StepProfile profile;
  double time = 0.0;
  double dt = 0.0;
  std::uint64_t steps = 0;
  std::uint64_t removed = 0;
  std::uint64_t clamped = 0;
  std::uint64_t initialFluid = 0;

  explicit Impl(const Scene& s) : scene(s) {
    calibration = sim::calibrate(scene);
    params = sim::fluidParameters(scene, calibration);
    domain = sim::domainParameters(scene);
    dt = calibration.initialDt;

    placeFluid();
    placeWalls();
    grid.cellSize = params.h;
    calibration.fluidParticles = initialFluid;
    calibration.boundaryParticles = boundary.count;
    // Density and pressure of the initial state, so stats and frame 0 are meaningful.
    removed += fluid::buildGrid(fluid, grid, domain);
    fluid::computeDensityAndPressure(fluid, grid, boundary, params);
  }

  // Samples the fluid blocks and sizes every per-particle array.
  void placeFluid() {
    std::vector<Vec3> points, velocities;
    for (const auto& block : scene.fluid.blocks) {
      auto blockPoints = sim::sampleBlock(block.box, scene.fluid.spacing);
      if (block.hydrostatic)
        sim::compressHydrostatically(blockPoints, block.box, scene.gravity, calibration.soundSpeed);
      const Vec3 v{float(block.velocity[0]), float(block.velocity[1]), float(block.velocity[2])};
      points.insert(points.end(), blockPoints.begin(), blockPoints.end());
      velocities.insert(velocities.end(), blockPoints.size(), v);
    }
    const std::size_t n = points.size();
    initialFluid = n;
    fluid.count = n;
    for (auto* b : {&fluid.position, &fluid.velocity, &fluid.acceleration, &fluid.scratch4,
                    &fluid.pressureState})
      b->resize(n);
    for (auto* b : {&fluid.id, &fluid.cell, &fluid.order, &fluid.scratchId, &fluid.neighborCount})
      b->resize(n);
    fluid.density.resize(n);
    fluid.pressure.resize(n);
    // Twice the neighbours of a particle in the initial lattice leaves room for compression.
    const double ratio = scene.fluid.supportRatio;
    fluid.neighborStride =
        static_cast<std::uint32_t>(std::ceil(2.0 * 4.0 / 3.0 * kPi * ratio * ratio * ratio));
    fluid.neighbors.resize(n * fluid.neighborStride);
    for (std::size_t i = 0; i < n; ++i) {
      fluid.position[i] = makeVec4(points[i]);
      fluid.velocity[i] = makeVec4(velocities[i]);
      fluid.acceleration[i] = Vec4{0, 0, 0, 0};
      fluid.id[i] = static_cast<std::uint32_t>(i);
    }
  }

  // Samples the tanks' walls; their ids follow the fluid's.
  void placeWalls() {
    std::vector<Vec3> points;
    for (const auto& tank : scene.walls) {
      const auto tankPoints = sim::sampleTank(tank, scene.fluid.spacing, scene.gravity);
      points.insert(points.end(), tankPoints.begin(), tankPoints.end());
    }
    boundary.count = points.size();
    boundary.position.resize(boundary.count);
    boundary.id.resize(boundary.count);
    for (std::size_t b = 0; b < boundary.count; ++b) {
      boundary.position[b] = makeVec4(points[b]);
      boundary.id[b] = static_cast<std::uint32_t>(initialFluid + b);
    }
    fluid::prepareBoundary(boundary, params);
  }

  double chooseTimeStep(double until) {
    const fluid::StepMeasures m = fluid::measureStep(fluid, params.restDensity);
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
    const fluid::BadParticle bad = fluid::findBadParticle(fluid, params.restDensity, bound);
    std::ostringstream message;
    message << "simulation failed at step " << steps << " (t = " << time << " s): particle "
            << bad.id << ": " << bad.quantity << " = " << bad.value;
    if (bad.pastBound) message << ", past failure.max_density_error = " << bound;
    throw SimulationFailure(message.str(), steps, bad.id, bad.quantity);
  }
};

}  // namespace sph
