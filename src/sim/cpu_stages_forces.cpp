// The CPU's force stages, compiled apart (cpu_stage_instances.hpp).
#include "sim/cpu_stage_instances.hpp"

namespace sph::fluid {

template void computeForces<CpuBackend>(FluidParticles<CpuBackend>&, const Grid<CpuBackend>&,
                                        const BoundaryParticles<CpuBackend>&,
                                        const BoundaryParticles<CpuBackend>&,
                                        const FluidParameters&, NeighborWalk);
template void wallForces<CpuBackend>(const FluidParticles<CpuBackend>&, const Grid<CpuBackend>&,
                                     const BoundaryParticles<CpuBackend>&, const FluidParameters&,
                                     const std::uint8_t*, Vec4*);

}  // namespace sph::fluid
