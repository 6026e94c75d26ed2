// A build without MPI: every run is one process's.
#include <cstdlib>

#include "run_processes.hpp"
#include "sph/error.hpp"
#include "sph/process_group.hpp"

namespace sph::cli {

struct RunProcesses::Impl {};

RunProcesses::RunProcesses(const RunOptions&) {
  if (startedAmongProcesses())
    throw InputError(
        "run: started among several processes (mpirun), but this build of sph has no MPI; "
        "build it with -DSPH_WITH_MPI=ON (libopenmpi-dev, libtrilinos-zoltan-dev) or run one "
        "process");
}
RunProcesses::~RunProcesses() = default;
bool RunProcesses::built() {
  return false;
}
int RunProcesses::rank() const {
  return 0;
}
int RunProcesses::ranks() const {
  return 1;
}
int RunProcesses::device(int device) const {
  return device;
}
bool RunProcesses::any(bool mine) const {
  return mine;
}
void RunProcesses::barrier() const {}
void RunProcesses::abort(int code) const {
  std::exit(code);
}
void RunProcesses::distribute(Simulation&) {}
nlohmann::json RunProcesses::summary() const {
  return nullptr;
}

}  // namespace sph::cli
