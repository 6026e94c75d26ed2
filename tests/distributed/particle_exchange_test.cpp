// Particles between ranks: migration loses, duplicates and alters nothing; the halo brings
// every particle within reach of a rank's own, and nothing it already owns.
#include "distributed/particle_exchange.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "distributed/partition.hpp"
#include "distributed_fixtures.hpp"

namespace sph::distributed {
namespace {

// After a partition: every id once over all ranks, each on the rank it was given, in id
// order, its values intact.
void expectWhole(const Communicator& comm, const ParticleRecords& owned, bool sheared = false) {
  EXPECT_TRUE(std::is_sorted(owned.id.begin(), owned.id.end()));
  for (std::size_t i = 0; i < owned.size(); ++i)
    ASSERT_TRUE(test::intact(owned, i, sheared)) << owned.id[i];
  const ParticleRecords all = test::everyone(comm, owned);
  const std::uint32_t n = test::kSide * test::kSide * test::kSide;
  ASSERT_EQ(all.size(), std::size_t(n)) << "lost or duplicated";
  for (std::uint32_t id = 0; id < n; ++id) ASSERT_EQ(all.id[id], id);
}

ParticleRecords partitioned(const Communicator& comm, GeometricPartitioner& partitioner,
                            const ParticleRecords& held) {
  return migrate(comm, held, partitioner.assign(test::positions(held), {}));
}

TEST(Migration, MovesEveryParticleOnceWithItsValues) {
  const Communicator comm;
  GeometricPartitioner partitioner(comm, PartitionMethod::Rcb);
  const ParticleRecords held = test::scattered(comm);
  const std::vector<int> owner = partitioner.assign(test::positions(held), {});
  std::size_t staying = 0;
  for (int r : owner) staying += r == comm.rank();
  const ParticleRecords owned = migrate(comm, held, owner);
  expectWhole(comm, owned);
  // Those it kept, and those each other rank was told to send it.
  EXPECT_EQ(comm.sum(std::uint64_t(owned.size())), comm.sum(std::uint64_t(held.size())));
  EXPECT_GE(owned.size(), staying);
}

// The particles move (the upper half along x); partitioned again, the moved ones change ranks and
// nothing is lost.
TEST(Migration, FollowsTheParticlesAsTheyMove) {
  const Communicator comm;
  GeometricPartitioner partitioner(comm, PartitionMethod::Rcb);
  ParticleRecords owned = partitioned(comm, partitioner, test::scattered(comm));
  for (std::size_t i = 0; i < owned.size(); ++i) test::shear(owned.value.data() + i * test::kWidth);
  const std::vector<int> owner = partitioner.assign(test::positions(owned), {});
  const std::uint64_t leaving = comm.sum(std::uint64_t(
      std::count_if(owner.begin(), owner.end(), [&](int r) { return r != comm.rank(); })));
  EXPECT_GT(leaving, 0u);
  expectWhole(comm, migrate(comm, owned, owner), true);
}

TEST(Migration, RefusesAnOwnerOutsideTheRun) {
  const Communicator comm;
  const ParticleRecords held = test::scattered(comm);
  std::vector<int> owner(held.size(), comm.size());
  EXPECT_THROW(migrate(comm, held, owner), std::invalid_argument);
  EXPECT_THROW(migrate(comm, held, {}), std::invalid_argument);
}

TEST(Halo, HoldsEveryParticleWithinReachOfARanksOwn) {
  const Communicator comm;
  GeometricPartitioner partitioner(comm, PartitionMethod::Rcb);
  const ParticleRecords owned = partitioned(comm, partitioner, test::scattered(comm));
  const float reach = 2.0f * test::kSpacing;  // a support radius of twice the spacing
  const HaloPlan plan = planHalo(comm, owned, reach);
  ParticleRecords halo = exchangeHalo(comm, plan, owned);
  halo.sortById();
  for (std::size_t i = 0; i < halo.size(); ++i) ASSERT_TRUE(test::intact(halo, i));
  for (std::size_t i = 1; i < halo.size(); ++i) ASSERT_NE(halo.id[i], halo.id[i - 1]);
  for (std::uint32_t id : halo.id)
    ASSERT_FALSE(std::binary_search(owned.id.begin(), owned.id.end(), id)) << "owned here";

  // Brute force: every other rank's particle within reach of one of this rank's.
  const ParticleRecords all = test::everyone(comm, owned);
  std::size_t needed = 0;
  for (std::size_t j = 0; j < all.size(); ++j) {
    if (std::binary_search(owned.id.begin(), owned.id.end(), all.id[j])) continue;
    const float* q = all.of(j);
    bool within = false;
    for (std::size_t i = 0; i < owned.size() && !within; ++i) {
      const float* p = owned.of(i);
      const float d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                       (p[2] - q[2]) * (p[2] - q[2]);
      within = d2 <= reach * reach;
    }
    if (!within) continue;
    ++needed;
    ASSERT_TRUE(std::binary_search(halo.id.begin(), halo.id.end(), all.id[j]))
        << "particle " << all.id[j] << " is within reach but not in the halo";
  }
  EXPECT_GT(needed, 0u);
  // RCB's regions are slabs of the block: the halo is a few layers of it, not the rest.
  EXPECT_LT(halo.size(), owned.size());
  EXPECT_EQ(comm.sum(std::uint64_t(plan.sent())), comm.sum(std::uint64_t(halo.size())));
}

// Refreshing a field of the halo by the same plan (as after a density pass) brings the new
// values in the same order.
TEST(Halo, RefreshesByThePlanItWasMadeWith) {
  const Communicator comm;
  GeometricPartitioner partitioner(comm, PartitionMethod::Rcb);
  const ParticleRecords owned = partitioned(comm, partitioner, test::scattered(comm));
  const HaloPlan plan = planHalo(comm, owned, 2.0f * test::kSpacing);
  const ParticleRecords halo = exchangeHalo(comm, plan, owned);
  ParticleRecords density;
  density.width = 1;
  density.id = owned.id;
  for (std::uint32_t id : owned.id) density.value.push_back(1000.0f + float(id));
  const ParticleRecords refreshed = exchangeHalo(comm, plan, density);
  ASSERT_EQ(refreshed.id, halo.id);
  for (std::size_t i = 0; i < refreshed.size(); ++i)
    EXPECT_EQ(refreshed.value[i], 1000.0f + float(refreshed.id[i]));
}

}  // namespace
}  // namespace sph::distributed
