// Read from the environment an MPI launcher gives its processes, so that a build without MPI
// can tell it was started by one too.
#include <cstdlib>

#include "sph/process_group.hpp"

namespace sph {

bool startedAmongProcesses() {
  // OpenMPI's launcher, then the PMI launchers' (MPICH's hydra, Slurm's srun).
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && std::atoi(value) > 1) return true;
  }
  return false;
}

}  // namespace sph
