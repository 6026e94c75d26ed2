// GoogleTest under MPI: every rank runs every test (they are collective); rank 0 prints the
// progress, every rank its own failures, and the run fails when any rank's test failed.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdio>

#include "distributed/communicator.hpp"

namespace {

// The failures of a rank other than 0, named by rank.
class RankFailures : public testing::EmptyTestEventListener {
 public:
  explicit RankFailures(int rank) : rank_(rank) {}
  void OnTestPartResult(const testing::TestPartResult& result) override {
    if (!result.failed()) return;
    std::fprintf(stderr, "[rank %d] %s:%d: Failure\n%s\n", rank_, result.file_name(),
                 result.line_number(), result.summary());
  }

 private:
  int rank_;
};

}  // namespace

int main(int argc, char** argv) {
  sph::distributed::MpiSession mpi(argc, argv);
  testing::InitGoogleTest(&argc, argv);
  const sph::distributed::Communicator world;
  if (world.rank() != 0) {
    testing::TestEventListeners& listeners = testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new RankFailures(world.rank()));
  }
  const int failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
  int anyFailed = 0;
  MPI_Allreduce(&failed, &anyFailed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return anyFailed;
}
