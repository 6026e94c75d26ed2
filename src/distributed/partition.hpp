// Which rank owns which particles: Zoltan's geometric partitioning (Boman et al., "Zoltan:
// Data-Management Services for Parallel Applications"), recursive coordinate bisection (RCB:
// axis-aligned cuts, each rank a box) or the Hilbert space-filling curve (HSFC), weighted by
// each particle's measured work. Called again on the particles as they are, it moves the cuts
// only as far as the work moved (RCB_REUSE), so a rebalance migrates few particles.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "distributed/communicator.hpp"

namespace sph::distributed {

enum class PartitionMethod { Rcb, Hsfc };

// "rcb", "hsfc"; and back (none for another name).
const char* partitionMethodName(PartitionMethod method);

class GeometricPartitioner {
 public:
  // Zoltan is initialised on first use in the process. Throws std::runtime_error when Zoltan
  // cannot be set up.
  GeometricPartitioner(const Communicator& comm, PartitionMethod method);
  ~GeometricPartitioner();
  GeometricPartitioner(const GeometricPartitioner&) = delete;
  GeometricPartitioner& operator=(const GeometricPartitioner&) = delete;

  // Each rank passes the particles it holds (x, y, z each) and their work (empty: 1 each), in
  // a collective call; returns for each of them the rank that is to own it. Deterministic: the
  // same particles on the same ranks give the same answer.
  std::vector<int> assign(const std::vector<float>& points, const std::vector<float>& work);
  // Each of this rank's points' rank by the cuts the last assign made (kept: nothing is
  // partitioned again, nothing crosses ranks): where a particle that moved now belongs. Under
  // RCB a point still in this rank's box, its faces included, stays. Throws std::logic_error
  // before the first assign.
  std::vector<int> owners(const std::vector<float>& points) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph::distributed
