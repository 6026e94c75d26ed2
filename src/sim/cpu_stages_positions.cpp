// The CPU's position solver, compiled apart (cpu_stage_instances.hpp).
#include "sim/cpu_stage_instances.hpp"

namespace sph::fluid {

template SolverReport solvePositions<CpuBackend>(FluidParticles<CpuBackend>&,
                                                 const Grid<CpuBackend>&,
                                                 const BoundaryParticles<CpuBackend>&,
                                                 const BoundaryParticles<CpuBackend>&,
                                                 const FluidParameters&, const PbfSettings&, float,
                                                 const DomainParameters&, NeighborWalk);
template void smoothVelocities<CpuBackend>(FluidParticles<CpuBackend>&, const Grid<CpuBackend>&,
                                           const BoundaryParticles<CpuBackend>&,
                                           const BoundaryParticles<CpuBackend>&,
                                           const FluidParameters&, float, NeighborWalk);

}  // namespace sph::fluid
