// The processes of a distributed run (MPI): who this one is, and the few collective operations
// the distributed step needs, on byte buffers and scalars. The transport is OpenMPI's; nothing
// here knows what a particle is (particle_exchange.hpp packs them).
#pragma once

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sph::distributed {

// MPI for the process: initialised (with threads funnelled through the main one: OpenMP's
// workers never call MPI) when made, finalised when destroyed. One per process, made before
// any Communicator.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};

class Communicator {
 public:
  explicit Communicator(MPI_Comm comm = MPI_COMM_WORLD);

  int rank() const { return rank_; }
  int size() const { return size_; }
  MPI_Comm handle() const { return comm_; }
  // The rank among the processes on this node (a GPU per rank picks its device by it).
  int localRank() const;

  double sum(double value) const;
  std::uint64_t sum(std::uint64_t value) const;
  double min(double value) const;
  double max(double value) const;
  // Every rank's value, by rank.
  std::vector<double> gather(double value) const;
  std::vector<float> allgather(const std::vector<float>& values) const;  // the same count each
  // Every rank's values (the same count each), by rank.
  std::vector<double> gather(const std::vector<double>& values) const;

  // Sends `send[r]` to rank r (itself included) and returns what each rank sent here, by source.
  std::vector<std::vector<std::byte>> exchange(
      const std::vector<std::vector<std::byte>>& send) const;

  void barrier() const;

 private:
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

}  // namespace sph::distributed
