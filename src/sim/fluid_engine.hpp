// The fluid state and its stages on one backend. Simulation drives the stages through this
// interface (one virtual call per stage, never per particle); EngineImpl<B> implements it once
// for every backend.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "fluid/measure_step.hpp"
#include "fluid/parameters.hpp"
#include "sph/core/vec.hpp"

namespace sph::sim {

// A host copy of the fluid particles, in the engine's current (cell) order.
struct HostParticles {
  std::vector<std::uint32_t> id;
  std::vector<Vec4> position;
  std::vector<Vec4> velocity;
  std::vector<float> density;
  std::vector<float> pressure;
  std::vector<Vec4> acceleration;  // w: |∇c|
};

struct HostWalls {
  std::vector<std::uint32_t> id;
  std::vector<Vec4> position;  // w: volume
};

class FluidEngine {
 public:
  virtual ~FluidEngine() = default;
  virtual const char* backendName() const = 0;
  virtual std::size_t fluidCount() const = 0;
  virtual std::size_t wallCount() const = 0;

  // The stages of a step, in order.
  virtual std::size_t buildGrid() = 0;  // returns the particles removed
  virtual void computeDensityAndPressure() = 0;
  virtual void computeForces() = 0;
  virtual fluid::StepMeasures measureStep() = 0;
  virtual std::size_t integrate(float dt) = 0;  // returns the particles clamped

  virtual fluid::BadParticle findBadParticle(float maxDensityError) const = 0;
  virtual HostParticles download() const = 0;
  virtual HostWalls downloadWalls() const = 0;
  // x, y, z, 0 per fluid particle id; empty removes the external accelerations.
  virtual void setExternalAcceleration(const std::vector<Vec4>& byId) = 0;
};

struct EngineSetup {
  fluid::FluidParameters params;
  fluid::DomainParameters domain;
  std::vector<Vec3> positions;   // fluid, by id
  std::vector<Vec3> velocities;  // fluid, by id
  std::vector<Vec3> walls;       // wall particles; their ids follow the fluid's
  std::uint32_t neighborStride = 0;
};

std::unique_ptr<FluidEngine> makeCpuEngine(const EngineSetup& setup);
// Throws InputError when this build has no CUDA backend or no GPU is usable.
std::unique_ptr<FluidEngine> makeCudaEngine(const EngineSetup& setup, int device);

}  // namespace sph::sim
