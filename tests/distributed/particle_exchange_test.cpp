// Particles between ranks as records: every record sent arrives whole, once, where it was
// sent, its values bit for bit; a partial record is refused.
#include "distributed/particle_exchange.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "distributed_fixtures.hpp"

namespace sph::distributed {
namespace {

TEST(Records, ArriveWholeOnceWhereTheyWereSent) {
  const Communicator comm;
  const ParticleRecords mine = test::scattered(comm);
  // Record i to rank id mod size, one further on than the rank holding it.
  std::vector<std::vector<std::byte>> send(std::size_t(comm.size()));
  for (std::size_t i = 0; i < mine.size(); ++i)
    packRecord(mine, i, send[(mine.id[i] / std::uint32_t(comm.size()) + 1) % comm.size()]);
  ParticleRecords arrived;
  arrived.width = mine.width;
  for (const std::vector<std::byte>& bytes : comm.exchange(send)) unpackRecords(bytes, arrived);
  for (std::size_t i = 0; i < arrived.size(); ++i) {
    ASSERT_TRUE(test::intact(arrived, i)) << arrived.id[i];
    EXPECT_EQ(int((arrived.id[i] / std::uint32_t(comm.size()) + 1) % comm.size()), comm.rank());
  }
  const std::uint64_t n = test::kSide * test::kSide * test::kSide;
  EXPECT_EQ(comm.sum(std::uint64_t(arrived.size())), n);
}

TEST(Records, APartialRecordIsRefused) {
  ParticleRecords into;
  into.width = test::kWidth;
  const std::vector<std::byte> cut(sizeof(std::uint32_t) + 2 * sizeof(float));
  EXPECT_THROW(unpackRecords(cut, into), std::runtime_error);
}

}  // namespace
}  // namespace sph::distributed
