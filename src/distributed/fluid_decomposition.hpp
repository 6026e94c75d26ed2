// The fluid across MPI processes (sim/decomposition.hpp, over this layer's partitioner and
// exchanges): Zoltan's cuts give each process its part, balancing the work (each particle
// weighed by the neighbours its last density pass listed); a particle that crosses a cut moves
// with all its fields and its id; copies of the particles in the cells next to another part
// are sent there as ghosts each step, and their densities again after the density pass. The
// cuts are kept from step to step and made again when the load has drifted: the busiest
// process's work over the mean more than `rebalanceAt` times what it was right after the last
// cuts.
#pragma once

#include <cstdint>
#include <vector>

#include "distributed/communicator.hpp"
#include "distributed/partition.hpp"
#include "sim/decomposition.hpp"

namespace sph::distributed {

struct DecompositionSettings {
  PartitionMethod method = PartitionMethod::Rcb;
  // How far the busiest process's work over the mean may drift from its value right
  // after the last partition before the cuts are made again (docs/distributed.md).
  double rebalanceAt = 1.05;
};

class FluidDecomposition final : public sim::Decomposition, public fluid::SolverGhosts {
 public:
  FluidDecomposition(const Communicator& comm, const DecompositionSettings& settings);

  int rank() const override { return comm_.rank(); }
  int size() const override { return comm_.size(); }
  std::size_t owned() const override { return ghostRows_.empty() ? 0 : ghostRows_.front(); }
  sim::Exchanged exchange(sim::HostFluidState& state,
                          const sim::ExchangeSettings& settings) override;
  sim::GhostDensities ghostDensities(const sim::HostDensities& densities) override;
  fluid::StepMeasures combine(const fluid::StepMeasures& local) override;
  fluid::BadParticle combine(const fluid::BadParticle& local) override;
  std::uint64_t sum(std::uint64_t local) override { return comm_.sum(local); }
  double sum(double local) override { return comm_.sum(local); }
  double max(double local) override { return comm_.max(local); }
  DistributedStats stats() const override;
  fluid::SolverGhosts& solverGhosts() override { return *this; }

  // fluid::SolverGhosts: the rows ghostDensities found, valid until the next exchange.
  const std::vector<std::uint32_t>& sentRows() const override { return sentRowsNow_; }
  const std::vector<std::uint32_t>& ghostRows() const override { return ghostRowsNow_; }
  std::vector<float> exchange(const std::vector<float>& sent, std::uint32_t width) override;
  void reduce(std::uint64_t& sum, std::uint64_t& count, std::uint64_t& largest) override;

 private:
  Communicator comm_;
  DecompositionSettings settings_;
  GeometricPartitioner partitioner_;
  bool partitioned_ = false;
  double imbalance_ = 1.0;  // of the last exchange
  // Right after the last partition: a lattice's planes, each kept whole, may leave it above 1,
  // and cutting again would give the same.
  double balanceWhenCut_ = 1.0;
  // The halo of the last exchange, by the rows of the state it gave: those of the particles sent
  // to each process, and each process's ghosts, rows ghostRows_[r] .. ghostRows_[r + 1].
  std::vector<std::vector<std::uint32_t>> sentRows_;
  std::vector<std::uint32_t> ghostRows_;
  std::size_t uploaded_ = 0;
  // The same rows after the grid: the sent, by destination, and the ghosts, by source.
  std::vector<std::uint32_t> sentRowsNow_, ghostRowsNow_;
  DistributedStats stats_;
  double ghostShareSum_ = 0.0, migratedSum_ = 0.0;
};

}  // namespace sph::distributed
