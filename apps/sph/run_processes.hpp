// The processes a run is divided among: several when mpirun started it (a build with MPI,
// sph/process_group.hpp), else this one alone, with every call below a no-op.
#pragma once

#include <memory>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sph/simulation.hpp"

namespace sph::cli {

class RunProcesses {
 public:
  // Starts MPI when an MPI launcher started this process among several. Throws InputError
  // when it did and this build has no MPI.
  explicit RunProcesses(const RunOptions& options);
  ~RunProcesses();
  RunProcesses(const RunProcesses&) = delete;
  RunProcesses& operator=(const RunProcesses&) = delete;

  // Whether this build runs across processes (MPI).
  static bool built();
  bool divided() const { return ranks() > 1; }
  int rank() const;
  int ranks() const;
  // The GPU this process runs on: `device` alone; under mpirun, the device that many further on
  // by its rank on its machine, round the machine's GPUs (two processes share one where it has
  // one).
  int device(int device) const;
  // Process 0 speaks for the run: its progress, its messages, its summary.
  bool lead() const { return rank() == 0; }
  bool any(bool mine) const;  // collective
  void barrier() const;
  // Ends every process with `code`: a failure one process met alone.
  [[noreturn]] void abort(int code) const;
  // The simulation as this process's part (Simulation::distribute) when divided.
  void distribute(Simulation& sim);
  // summary.json's "distributed": ranks, partition and what moved; null alone.
  nlohmann::json summary() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph::cli
