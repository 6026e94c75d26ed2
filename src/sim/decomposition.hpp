// A run across processes: each owns the fluid particles of its part of the space and holds, as
// ghosts, copies of the other parts' particles within reach of its own, so that its passes see
// every neighbour. The transport and the partitioning are the distributed layer's (sph_distributed,
// over MPI and Zoltan); the step calls it here, a few times a step, never per particle.
#pragma once

#include <cstdint>
#include <vector>

#include "fluid/dfsph_settings.hpp"
#include "fluid/measure_step.hpp"
#include "sim/fluid_engine.hpp"
#include "sph/distributed_stats.hpp"

namespace sph::sim {

// What an exchange is told of the scene.
struct ExchangeSettings {
  float reach = 0.0f;  // the support radius: a ghost is within it of a particle owned here
  Vec3 domainMin{0, 0, 0}, domainMax{0, 0, 0};  // particles outside it leave the run
};

// What an exchange did, the same on every process.
struct Exchanged {
  std::uint64_t removed = 0;  // particles that left the domain, over all processes
  // The bounds of every process's particles, for the grid (FluidStages::shareGrid).
  Vec3 gridLo{0, 0, 0}, gridHi{0, 0, 0};
  bool any = false;  // a particle is left anywhere
};

// Rows of the engine's arrays and the densities their owners computed.
struct GhostDensities {
  std::vector<std::uint32_t> rows;
  std::vector<float> density;
};

class Decomposition {
 public:
  virtual ~Decomposition() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // The particles this process owned after the last exchange (its ghosts aside).
  virtual std::size_t owned() const = 0;

  // Before the grid: `state` holds this process's particles as its engine has them (ghosts
  // marked, fluid::isGhost); afterwards, the particles it owns now, then the ghosts of the
  // others' next to its own. Collective.
  virtual Exchanged exchange(HostFluidState& state, const ExchangeSettings& settings) = 0;
  // After the grid of the state the last exchange gave and the density pass: the ghosts' rows
  // now and their owners' values. Collective.
  virtual GhostDensities ghostDensities(const HostDensities& densities) = 0;

  // Every process gets the same answer. Collective.
  virtual fluid::StepMeasures combine(const fluid::StepMeasures& local) = 0;
  // The bad particle with the lowest id over all processes (none found anywhere: found false).
  virtual fluid::BadParticle combine(const fluid::BadParticle& local) = 0;
  virtual std::uint64_t sum(std::uint64_t local) = 0;
  virtual double sum(double local) = 0;
  virtual double max(double local) = 0;

  virtual DistributedStats stats() const = 0;
  // The incompressible solver's ghosts, valid from ghostDensities to the next exchange.
  virtual fluid::SolverGhosts& solverGhosts() = 0;
};

}  // namespace sph::sim
