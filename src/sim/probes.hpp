// The scene's probes (README, "Probes"): the points they read, their columns in probes.csv,
// and their rows at output.probe_rate. A row's time is k / probe_rate exactly; its values are
// interpolated linearly between the states of the steps around it, so the rate is independent
// of the time step and of the frames.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sim/state_stream.hpp"
#include "sph/core/probe.hpp"
#include "sph/scene.hpp"
#include "sph/stats.hpp"

namespace sph::sim {

class ProbeSampler {
 public:
  // The scene's probes, checked by the scene loader. `spacing`: the fluid's, d; a level gauge
  // reads its line every d/4.
  ProbeSampler(const Scene& scene, double spacing);

  bool empty() const { return probes_.empty(); }
  // Where the fluid is to be sampled, each time the state changes.
  const std::vector<Vec3>& points() const { return points_; }
  // "<probe>_<quantity>_<unit>", in the order of each row's values.
  const std::vector<std::string>& columns() const { return columns_; }

  // The forces a force probe reads, by object and by wall.
  struct Forces {
    const std::vector<Vec3>& fluidOnObject;
    const std::vector<Vec3>& contactOnObject;  // the other objects' and the walls'
    const std::vector<Vec3>& fluidOnWall;      // empty when no probe reads a wall
  };
  // The state at time t: the fluid's sums at points() and the forces. Adds the rows due since
  // the last state up to t.
  void record(double t, const std::vector<PointSums>& sums, const Forces& forces);
  // The rows added since the last call.
  std::vector<ProbeRow> take();

  // Where the sampling stands: the last state's values, the next row's time and the rows not
  // yet taken (Simulation::saveState).
  void save(StateWriter& out) const;
  void load(StateReader& in);

 private:
  struct Probe {
    ProbeKind kind;
    std::size_t firstPoint = 0;  // into points_
    std::size_t pointCount = 0;
    float step = 0.0f;       // Level: between its points, m
    std::size_t object = 0;  // Force
    bool onWall = false;     // Force: `object` indexes the walls
  };
  std::vector<double> values(const std::vector<PointSums>& sums, const Forces& forces) const;

  std::vector<Probe> probes_;
  std::vector<Vec3> points_;
  std::vector<std::string> columns_;
  double rate_ = 0.0;
  std::size_t nextSample_ = 0;  // k of the next row's time k / rate
  bool recorded_ = false;
  double lastTime_ = 0.0;
  std::vector<double> lastValues_;
  std::vector<ProbeRow> rows_;
};

}  // namespace sph::sim
