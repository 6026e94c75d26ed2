// The stages of a fluid step, one file each. Each says what it reads and what it writes.
#pragma once

#include <cstddef>
#include <cstdint>

#include "fluid/parameters.hpp"
#include "fluid/particles.hpp"

namespace sph::fluid {

// Reads position, velocity, id. Writes them reordered by cell, grid.cellStart, count.
// Particles outside the domain are removed; returns how many.
std::size_t buildGrid(FluidParticles& fluid, Grid& grid, const DomainParameters& domain);

// Builds the walls' grid, sorts the wall particles by cell and sets each one's volume ψ_b.
// Once, at set-up.
void prepareBoundary(BoundaryParticles& boundary, const FluidParameters& params);

// Reads position, boundary. Writes density, pressure, pressureState and the neighbour lists
// (seed 1 Algorithm 1).
void computeDensityAndPressure(FluidParticles& fluid, const Grid& grid,
                               const BoundaryParticles& boundary, const FluidParameters& params);

// Reads position, velocity, pressureState, neighbour lists, boundary, externalById. Writes
// acceleration:
// pressure, viscosity, surface tension, gravity and external forces in one pass (seed 1
// Algorithm 2), and |∇c|.
void computeForces(FluidParticles& fluid, const Grid& grid, const BoundaryParticles& boundary,
                   const FluidParameters& params);

// What the time step and the failure check need, reduced over all fluid particles.
struct StepMeasures {
  float maxSpeed = 0.0f;
  float maxAcceleration = 0.0f;
  float maxDensityError = 0.0f;  // max (ρ/ρ0 - 1, 0): compression
  bool finite = true;            // no NaN or infinity in velocity, acceleration, density
};
StepMeasures measureStep(const FluidParticles& fluid, float restDensity);

// The first particle (lowest id) whose state is not finite or whose density error exceeds
// `maxDensityError`; names the quantity. Slow path, only after a failed measure.
struct BadParticle {
  bool found = false;
  std::uint32_t id = 0;
  const char* quantity = "";
  float value = 0.0f;
  bool pastBound = false;  // finite, but compressed past the bound
};
BadParticle findBadParticle(const FluidParticles& fluid, float restDensity, float maxDensityError);

// Symplectic Euler: v += dt a, then x += dt v; then the seed's damped box, or the clamp
// policy, keeps particles in the domain. Returns how many the clamp put back.
std::size_t integrate(FluidParticles& fluid, float dt, const DomainParameters& domain);

}  // namespace sph::fluid
