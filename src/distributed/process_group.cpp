#include "sph/process_group.hpp"

#include <cstdlib>
#include <optional>
#include <string>

#include "distributed/communicator.hpp"
#include "distributed/fluid_decomposition.hpp"
#include "sph/error.hpp"
#include "sph/simulation.hpp"

namespace sph {

struct ProcessGroup::Impl {
  std::optional<distributed::MpiSession> session;
  std::optional<distributed::Communicator> world;
  std::shared_ptr<distributed::FluidDecomposition> decomposition;
};

ProcessGroup::ProcessGroup() : impl_(std::make_unique<Impl>()) {
  int argc = 0;
  char** argv = nullptr;
  impl_->session.emplace(argc, argv);
  impl_->world.emplace();
}

ProcessGroup::~ProcessGroup() = default;

int ProcessGroup::rank() const {
  return impl_->world->rank();
}
int ProcessGroup::size() const {
  return impl_->world->size();
}
int ProcessGroup::localRank() const {
  return impl_->world->localRank();
}
bool ProcessGroup::any(bool mine) const {
  return impl_->world->max(mine ? 1.0 : 0.0) > 0.0;
}
void ProcessGroup::barrier() const {
  impl_->world->barrier();
}
void ProcessGroup::abort(int code) const {
  MPI_Abort(impl_->world->handle(), code);
  std::abort();  // MPI_Abort does not return
}

void ProcessGroup::distribute(Simulation& sim, const DistributeSettings& settings) {
  distributed::DecompositionSettings d;
  if (settings.partition == "hsfc")
    d.method = distributed::PartitionMethod::Hsfc;
  else if (settings.partition != "rcb")
    throw InputError("partition: expected \"rcb\" or \"hsfc\", got \"" + settings.partition + "\"");
  if (!(settings.rebalanceAt >= 1.0))
    throw InputError("rebalance_at: expected at least 1, got " +
                     std::to_string(settings.rebalanceAt));
  d.rebalanceAt = settings.rebalanceAt;
  auto decomposition = std::make_shared<distributed::FluidDecomposition>(*impl_->world, d);
  sim.distribute(decomposition);
  impl_->decomposition = std::move(decomposition);
}

DistributedStats ProcessGroup::stats() const {
  if (!impl_->decomposition) return DistributedStats{};
  return impl_->decomposition->stats();
}

}  // namespace sph
