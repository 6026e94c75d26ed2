// Meteer 2011, §8.1, solved: every parameter derived from the scene's geometry and material.
#pragma once

#include "fluid/parameters.hpp"
#include "interaction/object_particles.hpp"
#include "objects/object_world.hpp"
#include "sim/fluid_engine.hpp"
#include "sim/walls.hpp"
#include "sph/calibration.hpp"
#include "sph/core/time_step.hpp"

namespace sph::sim {

// Mass so that a particle inside the initial lattice has exactly the rest density; speed of
// sound ten times the largest expected speed; stiffness from it; the first time step.
// Throws InputError (naming the scene file and key) when a value cannot be derived.
// `attachedEngine`: objects of an engine attached to the simulation (no scene objects) take
// part, so the contact with them is calibrated as for the scene's own.
Calibration calibrate(const Scene& scene, bool attachedEngine = false);

fluid::FluidParameters fluidParameters(const Scene& scene, const Calibration& calibration);
// Without its periodic axes, which need the kernel's support: engineSetup adds them.
fluid::DomainParameters domainParameters(const Scene& scene);
Periodicity periodicity(const Scene& scene, float support);
// The bounds of every step (core/time_step.hpp), from the scene and its calibration.
StepLimits stepLimits(const Scene& scene, const Calibration& calibration);
// An engine's setup for the scene, all but the fluid particles: the parameters, the domain, the
// walls' particles and room for each particle's neighbour list. The caller adds the fluid.
EngineSetup engineSetup(const Scene& scene, const Calibration& calibration, const Walls& walls);
interaction::InteractionParameters interactionParameters(const Scene& scene,
                                                         const Calibration& calibration);
objects::WorldSettings worldSettings(const Scene& scene, const Calibration& calibration);

// The position solver's substep: no particle moves more than this many spacings in one (0.4 of
// its radius) at the largest expected speed.
constexpr double kPbfSubstepTravel = 0.2;
// The position solver's last guard: no particle's next predicted move passes this share of
// the support radius (Calibration::pbfSpeedGuard; at the derived substeps, 5 times the
// expected speed).
constexpr double kPbfGuardMove = 0.5;

// Σ_j |∇W(x_i - x_j)|² over an infinite cubic lattice of the given spacing.
double latticeGradientSquares(KernelKind kernel, double h, double spacing);

// Σ_j W(x_i - x_j) over an infinite cubic lattice of the given spacing, self included.
double latticeKernelSum(KernelKind kernel, double supportRadius, double spacing);

}  // namespace sph::sim
