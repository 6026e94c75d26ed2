// Stage: what the time step and the failure check need, reduced over the fluid.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid/parameters.hpp"
#include "fluid/particles.hpp"
#include "sph/core/eos.hpp"

namespace sph::fluid {

// What the time step and the failure check need, reduced over all fluid particles (a
// distributed run's ghosts left out: their owners measure them).
struct StepMeasures {
  float maxSpeed = 0.0f;
  float maxAcceleration = 0.0f;
  float maxDensityError = 0.0f;  // max (ρ/ρ0 - 1, 0): compression
  bool finite = true;            // no NaN or infinity in velocity, acceleration, density
};

struct BadParticle {
  bool found = false;
  std::uint32_t id = 0;
  const char* quantity = "";
  float value = 0.0f;
  bool pastBound = false;  // finite, but compressed past the bound
};

namespace detail {

SPH_HD StepMeasures combine(StepMeasures a, StepMeasures b) {
  return StepMeasures{a.maxSpeed > b.maxSpeed ? a.maxSpeed : b.maxSpeed,
                      a.maxAcceleration > b.maxAcceleration ? a.maxAcceleration : b.maxAcceleration,
                      a.maxDensityError > b.maxDensityError ? a.maxDensityError : b.maxDensityError,
                      a.finite && b.finite};
}

}  // namespace detail

template <class B>
StepMeasures measureStep(const FluidParticles<B>& fluid, float restDensity) {
  const Vec4* velocity = fluid.velocity.data();
  const Vec4* acceleration = fluid.acceleration.data();
  const float* density = fluid.density.data();
  const std::uint32_t* id = fluid.id.data();
  StepMeasures m = B::reduce(
      fluid.count, StepMeasures{},
      SPH_LAMBDA(std::size_t i) {
        if (isGhost(id[i])) return StepMeasures{};
        const Vec3 v = xyz(velocity[i]);
        const Vec3 a = xyz(acceleration[i]);
        const bool ok = isFinite(v) && isFinite(a) && isFinite(density[i]);
        return StepMeasures{lengthSquared(v), lengthSquared(a),
                            compression(density[i], restDensity), ok};
      },
      SPH_LAMBDA(StepMeasures a, StepMeasures b) { return detail::combine(a, b); });
  m.maxSpeed = sqrtf(m.maxSpeed);
  m.maxAcceleration = sqrtf(m.maxAcceleration);
  return m;
}

// The first particle (lowest id) whose state is not finite or whose compression exceeds
// `maxDensityError`; names the quantity. Slow path, only after a failed measure: it copies the
// arrays to the host.
template <class B>
BadParticle findBadParticle(const FluidParticles<B>& fluid, float restDensity,
                            float maxDensityError) {
  const std::size_t n = fluid.count;
  std::vector<Vec4> velocity(n), acceleration(n);
  std::vector<float> density(n);
  std::vector<std::uint32_t> id(n);
  B::download(fluid.velocity, velocity.data(), n);
  B::download(fluid.acceleration, acceleration.data(), n);
  B::download(fluid.density, density.data(), n);
  B::download(fluid.id, id.data(), n);
  BadParticle bad;
  for (std::size_t i = 0; i < n; ++i) {
    if (isGhost(id[i])) continue;
    const Vec3 v = xyz(velocity[i]);
    const Vec3 a = xyz(acceleration[i]);
    const float rho = density[i];
    const float excess = compression(rho, restDensity);
    BadParticle here;
    if (!isFinite(rho)) {
      here = {true, id[i], "density", rho};
    } else if (!isFinite(a)) {
      here = {true, id[i], "acceleration", length(a)};
    } else if (!isFinite(v)) {
      here = {true, id[i], "velocity", length(v)};
    } else if (excess > maxDensityError) {
      here = {true, id[i], "compression rho/rho0 - 1", excess, true};
    }
    if (here.found && (!bad.found || here.id < bad.id)) bad = here;
  }
  return bad;
}

}  // namespace sph::fluid
