// The CPU's density stages, compiled apart (cpu_stage_instances.hpp).
#include "sim/cpu_stage_instances.hpp"

namespace sph::fluid {

template void computeDensityAndPressure<CpuBackend>(FluidParticles<CpuBackend>&,
                                                    const Grid<CpuBackend>&,
                                                    const BoundaryParticles<CpuBackend>&,
                                                    const BoundaryParticles<CpuBackend>&,
                                                    const FluidParameters&, NeighborWalk);
template void integrateDensity<CpuBackend>(FluidParticles<CpuBackend>&, const Grid<CpuBackend>&,
                                           const BoundaryParticles<CpuBackend>&,
                                           const FluidParameters&, float, NeighborWalk);

}  // namespace sph::fluid
