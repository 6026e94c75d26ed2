// The library's entry point: a fluid simulation built from a Scene.
//
//   sph::Simulation sim(scene);
//   while (sim.time() < 1.0) sim.step();
//   sph::ParticleFrame frame = sim.frame();
#pragma once

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "sph/calibration.hpp"
#include "sph/fluid_draw.hpp"
#include "sph/frame.hpp"
#include "sph/live_parameters.hpp"
#include "sph/object_exchange.hpp"
#include "sph/object_surface.hpp"
#include "sph/scene.hpp"
#include "sph/simulation_options.hpp"
#include "sph/stats.hpp"
#include "sph/step_profile.hpp"

namespace sph {

namespace sim {
class Decomposition;  // sph_distributed makes one (distributed/fluid_decomposition.hpp)
}

// A frame and its statistics taken at one instant (Simulation::capture) and assembled later,
// on any thread: the simulation may step meanwhile.
class FrameCapture {
 public:
  FrameCapture(FrameCapture&&) noexcept;
  FrameCapture& operator=(FrameCapture&&) noexcept;
  ~FrameCapture();
  // Waits for the copy; call once. wallMsPerStep is left 0 for the caller to fill.
  void take(ParticleFrame& frame, FrameStats& stats);

 private:
  friend class Simulation;
  struct Impl;
  explicit FrameCapture(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

class Simulation {
 public:
  // Throws InputError if the scene cannot be simulated (e.g. no speed of sound derivable) or
  // the backend asked for is not available.
  explicit Simulation(const Scene& scene, const SimulationOptions& options = {});
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // One time step, shortened so as not to pass `until`. Throws SimulationFailure on a NaN,
  // an infinity or a density error past the scene's bound; the state is then the last good
  // one.
  void step(double until = std::numeric_limits<double>::infinity());
  // Steps until time() reaches t exactly.
  void advanceTo(double t);

  // Couples objects moved by an engine of your own (Meteer 2011, §4.3): from the next step on,
  // the fluid reads their surface particles from the newest publication of `exchange` and
  // deposits its force on each of them there (sph/object_exchange.hpp), pushing them by the
  // scene's `interaction` (contact forces, or boundary coupling under DFSPH) and pushed back
  // alike. Your engine takes the forces, steps and publishes in its own thread or between calls
  // to step(); the time step keeps its fastest particle from crossing a quarter of a fluid
  // particle's radius in one. Its objects are in frames as it last published them (ids after the
  // walls', by handle); objectStats() gives each one's fluid force alone (named by its id), and
  // saveState refuses. A scene whose `object_engine.type` is "bullet" makes none of its objects
  // and refuses to step until an engine is attached (BulletEngine::forScene makes one). A step
  // throws std::invalid_argument on a publication with a particle whose contact reach passes the
  // fluid's support radius. Throws std::logic_error when the scene has objects of its own or an
  // engine is attached already, std::invalid_argument on a null exchange.
  void attachObjectEngine(std::shared_ptr<ObjectExchange> exchange);
  // The fluid particles `ids` are held by object `object` of the attached engine (a vessel, a
  // closed soft body): from now on one found outside it counts as leaked (leakedCount,
  // leakedIds, leakPositions), as for a scene's own containers. Call after attachObjectEngine,
  // before the first step; throws std::logic_error otherwise, std::invalid_argument on an id
  // that is no fluid particle's or a negative object.
  void containFluid(std::int32_t object, const std::vector<std::uint32_t>& ids);

  // An external acceleration (m/s², added to gravity) for each fluid particle, by id:
  // `byId` holds x, y, z for ids 0 .. fluidParticles-1. It stays until replaced; an empty
  // vector removes it. Throws std::invalid_argument on a wrong size.
  void setExternalAcceleration(const std::vector<float>& byId);
  // Runs this simulation as one process of a run across several (MPI: every process builds the
  // same scene and calls this with its part of the decomposition before the first step; a
  // collective call, as step() is). From then on each process steps the particles it owns,
  // with copies of its neighbours' within reach; its frames hold the particles it owns, its
  // stats() every process's (collective too). Throws InputError naming the scene where it has what
  // is not yet run across processes (DFSPH or PBF, objects, emitters, outlets, probes, periodic
  // faces), std::logic_error after the first step, std::invalid_argument on null. saveState and
  // setExternalAcceleration refuse a distributed run (std::logic_error).
  void distribute(std::shared_ptr<sim::Decomposition> ranks);

  LiveParameters liveParameters() const;
  // From the next step on. c0² is proportional to the stiffness for every equation of state,
  // so the speed of sound, and with it the time step and the contact calibration, follow.
  // Throws InputError naming the key on a value out of range; nothing changes then.
  void setLiveParameters(const LiveParameters& values);
  // Moves the kinematic object `name` in a straight line to `offset` (m, from where it
  // started) over the next `arriveIn` seconds, and holds it there: a user dragging it.
  // Throws InputError when no kinematic object has that name.
  void steerObject(const std::string& name, const Vec3d& offset, double arriveIn);

  // The whole state between two steps — the particles, the clock and the adaptive step, the
  // counters, the incompressible solver's warm start, the emitters', outlets' and probes'
  // progress, the live parameters, and the objects: their engine's world (waited for), its
  // exchange with the fluid and the leak tracking — as bytes that loadState takes back. A
  // simulation built from the same scene that loads them steps on exactly as this one would:
  // on the CPU backend byte for byte, on any thread count. Throws OutputError when `out` fails.
  void saveState(std::ostream& out) const;
  // Throws InputError saying why when `in` is not a state this build of sph wrote (another
  // format version), is cut short or corrupted (its checksum), or was saved from another scene
  // (its particle counts, solver, emitters, outlets, probes or spacing); nothing changes then.
  void loadState(std::istream& in);

  double time() const;
  std::uint64_t stepCount() const;
  double lastDt() const;
  std::uint64_t removedCount() const;  // fluid particles that left the domain or drained
  std::uint64_t emittedCount() const;  // fluid particles the emitters put in
  // Times the scene's "clamp" policy put a particle back into the domain (particle-steps):
  // this process's in a run across processes, whose stats() has every process's.
  std::uint64_t clampedCount() const;
  // The fluid particles: this process's own in a run across processes (distribute).
  std::uint64_t fluidCount() const;
  const char* backendName() const;  // "cpu" or "cuda"
  const Scene& scene() const;
  const Calibration& calibration() const;
  const StepProfile& lastProfile() const;
  // The stages a step of this scene runs, in order, as named in the solver's stage list
  // (docs/design.md): only those the scene gives work.
  std::vector<std::string> stageNames() const;
  SolverStats lastSolve() const;

  // Each emitter's and each outlet's fluid since the start, in the scene's order.
  std::vector<FlowStats> emitterStats() const;
  std::vector<FlowStats> outletStats() const;
  // The objects of the scene, as their engine has them now.
  std::vector<ObjectStats> objectStats() const;
  // Fluid particles outside the object that held them at the start (Meteer 2011, §9), counting
  // those that were removed after leaving.
  std::uint64_t leakedCount() const;
  // Where each particle that ever left its container first left it (x, y, z per particle).
  std::vector<float> leakPositions() const;
  // The ids of the fluid particles outside their container now.
  std::vector<std::uint32_t> leakedIds() const;

  // The probes' columns, "<probe>_<quantity>_<unit>": pressure_Pa, density_kg_m3, vx_m_s ..
  // for a point, level_m for a level gauge, fx_N .. for a force. Empty without probes.
  const std::vector<std::string>& probeColumns() const;
  // The probes' rows since the last call, at the probe rate: each interpolated linearly in time
  // between the states of the steps around it (a frame's state: the positions a step ended at,
  // the densities and pressures it computed).
  std::vector<ProbeRow> takeProbeRows();

  // Statistics of the current state; wallMsPerStep is left 0 for the caller to fill.
  FrameStats stats() const;
  // The frame (fluid and objects) and the statistics of the current state, assembled when
  // taken: on the GPU the particles cross to pinned host memory while the next steps run.
  FrameCapture capture() const;
  // The particles ordered by id: fluid first, then walls if asked.
  ParticleFrame frame(bool includeBoundary = true) const;
  // The fluid's arrays read in place, without a copy (CPU backend; see FluidView).
  FluidView fluidView() const;
  // The static wall particles alone (they never move: runs write them once).
  ParticleFrame boundaryFrame() const;
  // The surfaces the built-in objects are drawn with (sph/object_surface.hpp), anchored on the
  // particle ids of the frames; none for an attached engine's objects.
  std::vector<ObjectSurfaceMesh> objectSurfaces() const;
  // The walls (if asked) and the objects, without the fluid: what a renderer draws beside a
  // fluid it takes through writeFluidForDrawing.
  ParticleFrame solidFrame(bool includeBoundary) const;

  // Writes the fluid particles, in the engine's order (not by id), into `target`'s arrays in
  // the backend's own memory, and returns how many: device pointers on the CUDA backend (an
  // OpenGL buffer mapped through CUDA–OpenGL interop, so drawing needs no host copy), host
  // pointers on the CPU. On the GPU the writes are queued on the default stream; unmapping the
  // buffers or synchronising orders them before a draw. Throws std::invalid_argument when
  // target.capacity < fluidCount(), a needed pointer is null or the positions are not 16-byte
  // aligned; nothing is written then.
  std::size_t writeFluidForDrawing(const FluidDrawTarget& target) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph
