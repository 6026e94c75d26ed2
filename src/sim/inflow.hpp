// Flow in: the scene's emitters, the zones their velocity holds, and the id the next particle
// they put gets (after the fluid's, the walls' and the objects').
#pragma once

#include <cstdint>

#include "sim/emitters.hpp"
#include "sim/fluid_engine.hpp"

namespace sph::sim {

struct Inflow {
  explicit Inflow(const Scene& scene) : emitters(scene), zones(emitters.zones()) {}

  // The layers due by time t enter the engine; returns how many particles entered.
  std::size_t emit(FluidEngine& engine, double t) {
    const NewParticles fresh = emitters.emit(t);
    if (fresh.position.empty()) return 0;
    engine.addParticles(fresh.position, fresh.velocity, nextId);
    nextId += std::uint32_t(fresh.position.size());
    return fresh.position.size();
  }

  Emitters emitters;
  fluid::InflowZones zones;
  std::uint32_t nextId = 0;
};

}  // namespace sph::sim
