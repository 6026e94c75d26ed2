#include <cmath>

#include "backend/cpu_parallel.hpp"
#include "fluid/stages.hpp"

namespace sph::fluid {

namespace {

// Compression only: a free surface's particles lack neighbours and read low, which is not
// an error of the method.
SPH_HD float densityError(float density, float restDensity) {
  const float e = density / restDensity - 1.0f;
  return e > 0.0f ? e : 0.0f;
}

SPH_HD StepMeasures combine(StepMeasures a, StepMeasures b) {
  return StepMeasures{a.maxSpeed > b.maxSpeed ? a.maxSpeed : b.maxSpeed,
                      a.maxAcceleration > b.maxAcceleration ? a.maxAcceleration : b.maxAcceleration,
                      a.maxDensityError > b.maxDensityError ? a.maxDensityError : b.maxDensityError,
                      a.finite && b.finite};
}

}  // namespace

StepMeasures measureStep(const FluidParticles& fluid, float restDensity) {
  const Vec4* velocity = fluid.velocity.data();
  const Vec4* acceleration = fluid.acceleration.data();
  const float* density = fluid.density.data();
  StepMeasures m = backend::reduce(
      fluid.count, StepMeasures{},
      SPH_LAMBDA(std::size_t i) {
        const Vec3 v = xyz(velocity[i]);
        const Vec3 a = xyz(acceleration[i]);
        const bool ok = isFinite(v) && isFinite(a) && isFinite(density[i]);
        return StepMeasures{lengthSquared(v), lengthSquared(a),
                            densityError(density[i], restDensity), ok};
      },
      SPH_LAMBDA(StepMeasures a, StepMeasures b) { return combine(a, b); });
  m.maxSpeed = sqrtf(m.maxSpeed);
  m.maxAcceleration = sqrtf(m.maxAcceleration);
  return m;
}

BadParticle findBadParticle(const FluidParticles& fluid, float restDensity, float maxDensityError) {
  BadParticle bad;
  for (std::size_t i = 0; i < fluid.count; ++i) {
    const Vec3 v = xyz(fluid.velocity[i]);
    const Vec3 a = xyz(fluid.acceleration[i]);
    const float rho = fluid.density[i];
    BadParticle here;
    if (!isFinite(rho)) {
      here = {true, fluid.id[i], "density", rho};
    } else if (!isFinite(a)) {
      here = {true, fluid.id[i], "acceleration", length(a)};
    } else if (!isFinite(v)) {
      here = {true, fluid.id[i], "velocity", length(v)};
    } else if (densityError(rho, restDensity) > maxDensityError) {
      here = {true, fluid.id[i], "compression rho/rho0 - 1", densityError(rho, restDensity), true};
    }
    if (here.found && (!bad.found || here.id < bad.id)) bad = here;
  }
  return bad;
}

}  // namespace sph::fluid
