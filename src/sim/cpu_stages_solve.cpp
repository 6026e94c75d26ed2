// The CPU's incompressible solve, compiled apart (cpu_stage_instances.hpp).
#include "sim/cpu_stage_instances.hpp"

namespace sph::fluid {

template SolverReport solve<CpuBackend>(FluidParticles<CpuBackend>&, const Grid<CpuBackend>&,
                                        const BoundaryParticles<CpuBackend>&,
                                        const BoundaryParticles<CpuBackend>&,
                                        const FluidParameters&, const SolverSettings&, SolverTarget,
                                        float, NeighborWalk, CoarsePressure&);

}  // namespace sph::fluid
