// The scene's emitters (flow in): where each puts its particles and when. Emitter k puts a
// layer on the fluid's lattice at times start + j d / U (j = 0, 1, ..., before `end`), each
// layer entering at the emitter's plane and moved on by U for the time since its moment; so
// that by time t it has put ceil((t - start) U / d) layers, a mass rate of
// (particles a layer) m U / d, the flux ρ0 U A of the opening at rest density.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fluid/drive_inflow.hpp"
#include "sim/state_stream.hpp"
#include "sph/core/vec.hpp"
#include "sph/scene.hpp"

namespace sph::sim {

struct NewParticles {
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;
};

class Emitters {
 public:
  explicit Emitters(const Scene& scene);

  bool empty() const { return emitters_.empty(); }
  std::size_t size() const { return emitters_.size(); }
  const std::string& name(std::size_t k) const { return emitters_[k].name; }
  std::size_t layerSize(std::size_t k) const { return emitters_[k].layer.size(); }
  std::uint64_t emitted(std::size_t k) const { return emitters_[k].emitted; }
  // Particles a second, while it runs.
  double particleRate(std::size_t k) const;
  // The most particles all emitters put in by time t.
  std::uint64_t emittedBy(double t) const;

  // The regions driveInflow holds at each emitter's velocity: two spacings downstream.
  fluid::InflowZones zones() const;
  // The layers due by time t and not yet put, placed as they stand at t.
  NewParticles emit(double t);

  // What each has put so far (Simulation::saveState).
  void save(StateWriter& out) const;
  void load(StateReader& in);

 private:
  struct Emitter {
    std::string name;
    Vec3d origin;              // a point of the plane: the disc's centre, the rectangle's corner
    Vec3d normal;              // unit, the direction of flow
    std::vector<Vec3d> layer;  // the lattice, relative to origin
    double speed, start, end;
    fluid::InflowZone zone;
    std::uint64_t layers = 0;  // put so far
    std::uint64_t emitted = 0;
  };
  std::uint64_t layersBy(const Emitter& e, double t) const;
  double spacing_;
  std::vector<Emitter> emitters_;
};

}  // namespace sph::sim
