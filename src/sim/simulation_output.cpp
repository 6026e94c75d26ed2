// What a Simulation reports: statistics and frames, computed on demand at output times.
#include <algorithm>

#include "sim/simulation_impl.hpp"

namespace sph {

namespace {

struct Sums {
  double kineticEnergy = 0.0;
  double density = 0.0;
  float maxDensityError = 0.0f;
  float maxSpeedSquared = 0.0f;
  std::uint64_t surface = 0;
};

}  // namespace

FrameStats Simulation::stats() const {
  const Impl& s = *impl_;
  const fluid::FluidParticles& f = s.fluid;
  const float restDensity = s.params.restDensity;
  const float threshold = s.params.surfaceThreshold;
  const Sums sums = backend::reduce(
      f.count, Sums{},
      [&](std::size_t i) {
        const float v2 = lengthSquared(xyz(f.velocity[i]));
        const float error = std::abs(f.density[i] / restDensity - 1.0f);
        return Sums{0.5 * s.params.mass * v2, f.density[i], error, v2,
                    f.acceleration[i].w > threshold ? 1u : 0u};
      },
      [](Sums a, const Sums& b) {
        a.kineticEnergy += b.kineticEnergy;
        a.density += b.density;
        a.maxDensityError = std::max(a.maxDensityError, b.maxDensityError);
        a.maxSpeedSquared = std::max(a.maxSpeedSquared, b.maxSpeedSquared);
        a.surface += b.surface;
        return a;
      });
  FrameStats out;
  out.time = s.time;
  out.steps = s.steps;
  out.dt = s.dt;
  out.fluidCount = f.count;
  out.boundaryCount = s.boundary.count;
  out.kineticEnergy = sums.kineticEnergy;
  out.meanDensity = f.count ? sums.density / double(f.count) : 0.0;
  out.maxDensityError = sums.maxDensityError;
  out.maxSpeed = std::sqrt(double(sums.maxSpeedSquared));
  out.surfaceCount = sums.surface;
  out.leakedCount = 0;  // no objects yet hold fluid
  out.removedCount = s.removed;
  return out;
}

ParticleFrame Simulation::frame(bool includeBoundary) const {
  const Impl& s = *impl_;
  const fluid::FluidParticles& f = s.fluid;
  const fluid::BoundaryParticles& b = s.boundary;
  // Fluid ids are 0 .. initialFluid-1 with gaps where particles were removed; walls follow.
  std::vector<std::int64_t> slotOfId(s.initialFluid, -1);
  for (std::size_t i = 0; i < f.count; ++i) slotOfId[f.id[i]] = static_cast<std::int64_t>(i);

  ParticleFrame out;
  out.time = s.time;
  out.step = s.steps;
  const std::size_t n = f.count + (includeBoundary ? b.count : 0);
  out.id.reserve(n);
  out.position.reserve(3 * n);
  out.velocity.reserve(3 * n);
  out.density.reserve(n);
  out.pressure.reserve(n);
  out.kind.reserve(n);
  out.object.reserve(n);
  auto push = [&](std::uint32_t id, Vec4 x, Vec4 v, float rho, float p, ParticleKind kind) {
    out.id.push_back(id);
    out.position.insert(out.position.end(), {x.x, x.y, x.z});
    out.velocity.insert(out.velocity.end(), {v.x, v.y, v.z});
    out.density.push_back(rho);
    out.pressure.push_back(p);
    out.kind.push_back(static_cast<std::uint8_t>(kind));
    out.object.push_back(-1);
  };
  for (std::int64_t slot : slotOfId) {
    if (slot < 0) continue;
    const auto i = static_cast<std::size_t>(slot);
    push(f.id[i], f.position[i], f.velocity[i], f.density[i], f.pressure[i], ParticleKind::Fluid);
  }
  if (includeBoundary) {
    std::vector<std::size_t> byId(b.count);
    for (std::size_t k = 0; k < b.count; ++k) byId[b.id[k] - s.initialFluid] = k;
    for (std::size_t k : byId)
      push(b.id[k], b.position[k], Vec4{0, 0, 0, 0}, s.params.restDensity, 0.0f,
           ParticleKind::Boundary);
  }
  return out;
}

}  // namespace sph
