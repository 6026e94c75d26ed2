// A run across processes (MPI; ProcessGroup is built with SPH_WITH_MPI): started by mpirun, every
// process builds the same simulation and hands it to its group, which divides the particles among
// them (Simulation::distribute; docs/distributed.md).
//
//   sph::ProcessGroup group;               // MPI for this process
//   sph::Simulation sim(scene);
//   group.distribute(sim);
//   while (sim.time() < 1.0) sim.step();   // every process, together
#pragma once

#include <memory>
#include <string>

#include "sph/distributed_stats.hpp"

namespace sph {

class Simulation;

// Whether an MPI launcher (mpirun, mpiexec, srun) started this process as one of several: the
// environment it gives its processes says so, before MPI is initialised. In every build, with
// MPI or without.
bool startedAmongProcesses();

struct DistributeSettings {
  std::string partition = "rcb";  // Zoltan's method: "rcb" (boxes) or "hsfc" (Hilbert curve)
  // How far the busiest process's work over the mean (its particles weighed by the neighbours
  // each listed) may drift from what it was right after the last partition before the
  // particles are partitioned again: at least 1.
  double rebalanceAt = 1.05;
};

class ProcessGroup {
 public:
  // Initialises MPI (finalised when destroyed): one group per process. Throws
  // std::runtime_error when MPI cannot start.
  ProcessGroup();
  ~ProcessGroup();
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;

  int rank() const;
  int size() const;
  // The rank among the processes on this machine: a process per GPU picks its device by it.
  int localRank() const;
  // Whether any process passed true. Collective.
  bool any(bool mine) const;
  void barrier() const;
  // Ends every process of the run with `code`: for a failure one process alone has met (its
  // disk), which the others would wait on forever.
  [[noreturn]] void abort(int code) const;

  // sim runs as this process's part (Simulation::distribute). Throws InputError on settings out
  // of range and as Simulation::distribute does.
  void distribute(Simulation& sim, const DistributeSettings& settings = {});
  // What the decomposition has moved so far (zeros before distribute).
  DistributedStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph
