// The CPU's fluid-object stages, compiled apart (cpu_stage_instances.hpp).
#include "sim/cpu_stage_instances.hpp"

namespace sph::interaction {

template std::size_t computeContacts<CpuBackend>(fluid::FluidParticles<CpuBackend>&,
                                                 const fluid::Grid<CpuBackend>&,
                                                 ObjectParticles<CpuBackend>&,
                                                 ContainmentState<CpuBackend>&,
                                                 const InteractionParameters&);
template void addBoundaryForces<CpuBackend>(const fluid::FluidParticles<CpuBackend>&,
                                            const fluid::Grid<CpuBackend>&,
                                            const fluid::BoundaryParticles<CpuBackend>&,
                                            ObjectParticles<CpuBackend>&,
                                            const fluid::FluidParameters&, bool);
template void addConstraintReactions<CpuBackend>(const fluid::FluidParticles<CpuBackend>&,
                                                 const fluid::BoundaryParticles<CpuBackend>&,
                                                 ObjectParticles<CpuBackend>&, float);

}  // namespace sph::interaction
