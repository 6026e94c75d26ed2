// What a run across processes moved between them (summary.json's "distributed").
#pragma once

#include <cstdint>

namespace sph {

struct DistributedStats {
  int ranks = 1;
  std::uint64_t exchanges = 0;     // one a step
  std::uint64_t repartitions = 0;  // cuts made again after the first, as the load drifted
  double rebalanceAt = 0.0;        // the drift that makes them (DistributeSettings)
  // The busiest process's work over the mean, last step: its particles weighed by the
  // neighbours each listed.
  double lastImbalance = 1.0;
  double largestImbalance = 1.0;
  double meanGhostShare = 0.0;       // ghosts over owned particles, mean over processes and steps
  double meanMigratedPerStep = 0.0;  // particles that changed process a step, all processes
};

}  // namespace sph
