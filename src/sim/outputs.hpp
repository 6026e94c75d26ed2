// What a run measures of itself beside the step: the probes, the fluid's force on the walls a
// probe reads, and the surface flags (|∇c|), measured when a frame or statistics want them,
// not in every step: the step needs them only for surface tension.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "sim/fluid_engine.hpp"
#include "sim/probes.hpp"
#include "sim/walls.hpp"
#include "sph/scene.hpp"

namespace sph::sim {

struct Outputs {
  std::unique_ptr<ProbeSampler> probes;
  std::vector<Vec3> fluidForceOnWall;       // by wall, last step; only when a probe asks
  std::vector<std::size_t> wallOfParticle;  // in the engine's wall order
  bool neighboursListed = false;            // a density pass has run: the surface can be measured
  mutable bool surfaceMeasured = false;

  void measureSurfaceIfStale(FluidEngine& engine) const {
    if (!surfaceMeasured && neighboursListed) engine.measureSurface();
    surfaceMeasured = true;
  }

  static bool probesWallForces(const Scene& scene);
  // Each wall particle's wall, and the engine told which walls a probe reads.
  void mapWallParticles(FluidEngine& engine, const Walls& walls, const Scene& scene,
                        std::size_t initialFluid);
  // The fluid's force on each probed wall this step, summed in the engine's wall order (the
  // same for any thread count); a pass over the probed walls' particles.
  void collectWallForces(FluidEngine& engine);
  // The probes read the state as it is now.
  void sampleProbes(FluidEngine& engine, double time, const std::vector<Vec3>& fluidForceOnObject,
                    const std::vector<Vec3>& contactForceOnObject);
};

}  // namespace sph::sim
