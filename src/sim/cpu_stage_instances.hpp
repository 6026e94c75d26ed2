// The CPU backend's heaviest stages, each instantiated in a file of its own (cpu_stages_*.cpp)
// rather than all in cpu_engine.cpp: each carries a pass for every kernel set and option, and
// the one file that held them all took a core six minutes to compile under the sanitizers while
// the other core waited. Declared here so that cpu_engine.cpp instantiates none of them.
#pragma once

#include <cstddef>
#include <cstdint>

#include "backend/cpu_backend.hpp"
#include "fluid/stages.hpp"
#include "interaction/stages.hpp"

namespace sph::fluid {

using backend::CpuBackend;

// cpu_stages_density.cpp
extern template void computeDensityAndPressure<CpuBackend>(FluidParticles<CpuBackend>&,
                                                           const Grid<CpuBackend>&,
                                                           const BoundaryParticles<CpuBackend>&,
                                                           const BoundaryParticles<CpuBackend>&,
                                                           const FluidParameters&, NeighborWalk);
extern template void integrateDensity<CpuBackend>(FluidParticles<CpuBackend>&,
                                                  const Grid<CpuBackend>&,
                                                  const BoundaryParticles<CpuBackend>&,
                                                  const FluidParameters&, float, NeighborWalk);

// cpu_stages_forces.cpp
extern template void computeForces<CpuBackend>(FluidParticles<CpuBackend>&, const Grid<CpuBackend>&,
                                               const BoundaryParticles<CpuBackend>&,
                                               const BoundaryParticles<CpuBackend>&,
                                               const FluidParameters&, NeighborWalk);
extern template void wallForces<CpuBackend>(const FluidParticles<CpuBackend>&,
                                            const Grid<CpuBackend>&,
                                            const BoundaryParticles<CpuBackend>&,
                                            const FluidParameters&, const std::uint8_t*, Vec4*);

// cpu_stages_solve.cpp
extern template SolverReport solve<CpuBackend>(FluidParticles<CpuBackend>&, const Grid<CpuBackend>&,
                                               const BoundaryParticles<CpuBackend>&,
                                               const BoundaryParticles<CpuBackend>&,
                                               const FluidParameters&, const SolverSettings&,
                                               SolverTarget, float, NeighborWalk, CoarsePressure&);

// cpu_stages_positions.cpp
extern template SolverReport solvePositions<CpuBackend>(
    FluidParticles<CpuBackend>&, const Grid<CpuBackend>&, const BoundaryParticles<CpuBackend>&,
    const BoundaryParticles<CpuBackend>&, const FluidParameters&, const PbfSettings&, float,
    const DomainParameters&, NeighborWalk);
extern template void smoothVelocities<CpuBackend>(FluidParticles<CpuBackend>&,
                                                  const Grid<CpuBackend>&,
                                                  const BoundaryParticles<CpuBackend>&,
                                                  const BoundaryParticles<CpuBackend>&,
                                                  const FluidParameters&, float, NeighborWalk);

}  // namespace sph::fluid

namespace sph::interaction {

using backend::CpuBackend;

// cpu_stages_objects.cpp
extern template std::size_t computeContacts<CpuBackend>(fluid::FluidParticles<CpuBackend>&,
                                                        const fluid::Grid<CpuBackend>&,
                                                        ObjectParticles<CpuBackend>&,
                                                        ContainmentState<CpuBackend>&,
                                                        const InteractionParameters&);
extern template void addBoundaryForces<CpuBackend>(const fluid::FluidParticles<CpuBackend>&,
                                                   const fluid::Grid<CpuBackend>&,
                                                   const fluid::BoundaryParticles<CpuBackend>&,
                                                   ObjectParticles<CpuBackend>&,
                                                   const fluid::FluidParameters&, bool);
extern template void addConstraintReactions<CpuBackend>(const fluid::FluidParticles<CpuBackend>&,
                                                        const fluid::BoundaryParticles<CpuBackend>&,
                                                        ObjectParticles<CpuBackend>&, float);

}  // namespace sph::interaction
