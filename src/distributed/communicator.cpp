#include "distributed/communicator.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sph::distributed {

namespace {

void check(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw std::runtime_error(std::string(what) + ": " + std::string(text, std::size_t(length)));
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  // Errors come back as codes, to be thrown with their text, not as an abort of every rank.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
}

MpiSession::~MpiSession() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

Communicator::Communicator(MPI_Comm comm) : comm_(comm) {
  check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

int Communicator::localRank() const {
  MPI_Comm node;
  check(MPI_Comm_split_type(comm_, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node),
        "MPI_Comm_split_type");
  int local = 0;
  MPI_Comm_rank(node, &local);
  MPI_Comm_free(&node);
  return local;
}

double Communicator::sum(double value) const {
  double out = 0.0;
  check(MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_SUM, comm_), "MPI_Allreduce");
  return out;
}

std::uint64_t Communicator::sum(std::uint64_t value) const {
  std::uint64_t out = 0;
  check(MPI_Allreduce(&value, &out, 1, MPI_UINT64_T, MPI_SUM, comm_), "MPI_Allreduce");
  return out;
}

double Communicator::min(double value) const {
  double out = 0.0;
  check(MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MIN, comm_), "MPI_Allreduce");
  return out;
}

double Communicator::max(double value) const {
  double out = 0.0;
  check(MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, comm_), "MPI_Allreduce");
  return out;
}

std::vector<double> Communicator::gather(double value) const {
  std::vector<double> out(std::size_t(size_), 0.0);
  check(MPI_Allgather(&value, 1, MPI_DOUBLE, out.data(), 1, MPI_DOUBLE, comm_), "MPI_Allgather");
  return out;
}

std::vector<float> Communicator::allgather(const std::vector<float>& values) const {
  std::vector<float> out(values.size() * std::size_t(size_));
  check(MPI_Allgather(values.data(), int(values.size()), MPI_FLOAT, out.data(), int(values.size()),
                      MPI_FLOAT, comm_),
        "MPI_Allgather");
  return out;
}

std::vector<double> Communicator::gather(const std::vector<double>& values) const {
  std::vector<double> out(values.size() * std::size_t(size_));
  check(MPI_Allgather(values.data(), int(values.size()), MPI_DOUBLE, out.data(), int(values.size()),
                      MPI_DOUBLE, comm_),
        "MPI_Allgather");
  return out;
}

std::vector<std::vector<std::byte>> Communicator::exchange(
    const std::vector<std::vector<std::byte>>& send) const {
  if (send.size() != std::size_t(size_))
    throw std::invalid_argument("Communicator::exchange: expected a buffer for each of the " +
                                std::to_string(size_) + " ranks, got " +
                                std::to_string(send.size()));
  // Sizes first, then the bytes in one all-to-all. Counts are ints in MPI: a rank's message
  // to another stays under 2 GiB (tens of millions of particles).
  const std::size_t ranks = std::size_t(size_);
  std::vector<int> sendCounts(ranks), receiveCounts(ranks);
  for (int r = 0; r < size_; ++r) {
    if (send[std::size_t(r)].size() > std::size_t(INT32_MAX))
      throw std::length_error("Communicator::exchange: a message over 2 GiB");
    sendCounts[std::size_t(r)] = int(send[std::size_t(r)].size());
  }
  check(MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT, comm_),
        "MPI_Alltoall");
  std::vector<int> sendOffsets(ranks), receiveOffsets(ranks);
  std::size_t sendTotal = 0, receiveTotal = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    sendOffsets[r] = int(sendTotal);
    receiveOffsets[r] = int(receiveTotal);
    sendTotal += std::size_t(sendCounts[r]);
    receiveTotal += std::size_t(receiveCounts[r]);
  }
  if (sendTotal > std::size_t(INT32_MAX) || receiveTotal > std::size_t(INT32_MAX))
    throw std::length_error("Communicator::exchange: over 2 GiB in one exchange");
  std::vector<std::byte> packed(sendTotal), received(receiveTotal);
  for (std::size_t r = 0; r < ranks; ++r)
    std::copy(send[r].begin(), send[r].end(), packed.begin() + sendOffsets[r]);
  check(
      MPI_Alltoallv(packed.data(), sendCounts.data(), sendOffsets.data(), MPI_BYTE, received.data(),
                    receiveCounts.data(), receiveOffsets.data(), MPI_BYTE, comm_),
      "MPI_Alltoallv");
  std::vector<std::vector<std::byte>> out(ranks);
  for (std::size_t r = 0; r < ranks; ++r)
    out[r].assign(received.begin() + receiveOffsets[r],
                  received.begin() + receiveOffsets[r] + receiveCounts[r]);
  return out;
}

void Communicator::barrier() const {
  check(MPI_Barrier(comm_), "MPI_Barrier");
}

}  // namespace sph::distributed
