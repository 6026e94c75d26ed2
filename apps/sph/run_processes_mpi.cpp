#include <optional>

#include "run_processes.hpp"
#include "sph/devices.hpp"
#include "sph/process_group.hpp"

namespace sph::cli {

struct RunProcesses::Impl {
  std::optional<ProcessGroup> group;
  DistributeSettings settings;
};

RunProcesses::RunProcesses(const RunOptions& options) : impl_(std::make_unique<Impl>()) {
  impl_->settings.partition = options.partition;
  impl_->settings.rebalanceAt = options.rebalanceAt;
  if (startedAmongProcesses()) impl_->group.emplace();
}

RunProcesses::~RunProcesses() = default;

bool RunProcesses::built() {
  return true;
}

int RunProcesses::rank() const {
  return impl_->group ? impl_->group->rank() : 0;
}
int RunProcesses::ranks() const {
  return impl_->group ? impl_->group->size() : 1;
}
int RunProcesses::device(int device) const {
  if (!divided()) return device;
  const int gpus = int(queryGpus().devices.size());
  const int local = device + impl_->group->localRank();
  return gpus > 0 ? local % gpus : local;
}
bool RunProcesses::any(bool mine) const {
  return impl_->group ? impl_->group->any(mine) : mine;
}
void RunProcesses::barrier() const {
  if (impl_->group) impl_->group->barrier();
}
void RunProcesses::abort(int code) const {
  if (impl_->group) impl_->group->abort(code);
  std::exit(code);
}
void RunProcesses::distribute(Simulation& sim) {
  if (divided()) impl_->group->distribute(sim, impl_->settings);
}

nlohmann::json RunProcesses::summary() const {
  if (!divided()) return nullptr;
  const DistributedStats s = impl_->group->stats();
  return {{"ranks", s.ranks},
          {"partition", impl_->settings.partition},
          {"rebalance_at", s.rebalanceAt},
          {"repartitions", s.repartitions},
          {"last_imbalance", s.lastImbalance},
          {"largest_imbalance", s.largestImbalance},
          {"mean_ghost_share", s.meanGhostShare},
          {"mean_migrated_per_step", s.meanMigratedPerStep}};
}

}  // namespace sph::cli
