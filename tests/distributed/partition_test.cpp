// Zoltan's geometric partitioning as the distributed step uses it: every particle gets one
// rank, the work is balanced, the answer repeats, and weights move the cuts.
#include "distributed/partition.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "distributed_fixtures.hpp"

namespace sph::distributed {
namespace {

// Particles each rank is to own, summed over the ranks that hold them now, by rank.
std::vector<double> ownedCounts(const Communicator& comm, const std::vector<int>& owner,
                                const std::vector<float>& work = {}) {
  std::vector<double> out(std::size_t(comm.size()));
  for (int r = 0; r < comm.size(); ++r) {
    double mine = 0.0;
    for (std::size_t i = 0; i < owner.size(); ++i)
      if (owner[i] == r) mine += work.empty() ? 1.0 : work[i];
    out[std::size_t(r)] = comm.sum(mine);
  }
  return out;
}

class Partition : public testing::TestWithParam<PartitionMethod> {};

TEST_P(Partition, GivesEveryParticleOneRankInBalance) {
  const Communicator comm;
  const ParticleRecords mine = test::scattered(comm);
  GeometricPartitioner partitioner(comm, GetParam());
  const std::vector<int> owner = partitioner.assign(test::positions(mine), {});
  ASSERT_EQ(owner.size(), mine.size());
  for (int r : owner) ASSERT_TRUE(r >= 0 && r < comm.size()) << r;
  const std::vector<double> counts = ownedCounts(comm, owner);
  const double total = double(test::kSide * test::kSide * test::kSide);
  double sum = 0.0;
  for (double c : counts) sum += c;
  EXPECT_EQ(sum, total);
  const double busiest = *std::max_element(counts.begin(), counts.end());
  EXPECT_LE(busiest / (total / comm.size()), 1.02) << "within Zoltan's 1 % tolerance and a layer";
}

TEST_P(Partition, RepeatsItsAnswer) {
  const Communicator comm;
  const ParticleRecords mine = test::scattered(comm);
  GeometricPartitioner first(comm, GetParam()), second(comm, GetParam());
  EXPECT_EQ(first.assign(test::positions(mine), {}), second.assign(test::positions(mine), {}));
}

// Three times the work on one side: the busy side is split among more ranks.
TEST_P(Partition, BalancesTheWorkNotTheCount) {
  const Communicator comm;
  const ParticleRecords mine = test::scattered(comm);
  const std::vector<float> p = test::positions(mine);
  std::vector<float> work(mine.size());
  for (std::size_t i = 0; i < mine.size(); ++i) work[i] = p[3 * i] < 0.115f ? 3.0f : 1.0f;
  GeometricPartitioner partitioner(comm, GetParam());
  const std::vector<int> owner = partitioner.assign(p, work);
  const std::vector<double> load = ownedCounts(comm, owner, work);
  const std::vector<double> counts = ownedCounts(comm, owner);
  double total = 0.0;
  for (double w : load) total += w;
  EXPECT_LE(*std::max_element(load.begin(), load.end()) / (total / comm.size()), 1.03);
  // RCB's boxes cannot mix the two sides as the Hilbert curve's pieces do: equal work is
  // unequal counts.
  if (GetParam() == PartitionMethod::Rcb) {
    EXPECT_GT(*std::max_element(counts.begin(), counts.end()) /
                  *std::min_element(counts.begin(), counts.end()),
              1.4);
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, Partition,
                         testing::Values(PartitionMethod::Rcb, PartitionMethod::Hsfc),
                         [](const testing::TestParamInfo<PartitionMethod>& info) {
                           return std::string(partitionMethodName(info.param));
                         });

}  // namespace
}  // namespace sph::distributed
