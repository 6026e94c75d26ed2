// The fluid state and its stages on one backend, behind interfaces split by concern: the
// step's stages, what the time-step guard measures, the fluid's side of the objects' coupling,
// and what outputs read. Simulation calls them once per stage, never per particle;
// EngineImpl<B> implements them once for every backend.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "fluid/dfsph_settings.hpp"
#include "fluid/drive_inflow.hpp"
#include "fluid/measure_step.hpp"
#include "fluid/parameters.hpp"
#include "fluid/pbf_settings.hpp"
#include "interaction/object_particles.hpp"
#include "sph/core/probe.hpp"
#include "sph/core/vec.hpp"
#include "sph/fluid_draw.hpp"
#include "sph/frame.hpp"
#include "sph/object_exchange.hpp"

namespace sph::sim {

// A host copy of the fluid particles, in the engine's current (cell) order.
struct HostParticles {
  std::vector<std::uint32_t> id;
  std::vector<Vec4> position;
  std::vector<Vec4> velocity;
  std::vector<float> density;
  std::vector<float> pressure;
  std::vector<Vec4> acceleration;  // w: |∇c|
};

// A download begun and not yet waited for (FluidEngine::beginDownload).
class PendingParticles {
 public:
  virtual ~PendingParticles() = default;
  // Waits for the copy; call once.
  virtual HostParticles take() = 0;
};

// A copy made already.
class ReadyParticles final : public PendingParticles {
 public:
  explicit ReadyParticles(HostParticles particles) : particles_(std::move(particles)) {}
  HostParticles take() override { return std::move(particles_); }

 private:
  HostParticles particles_;
};

// The fluid's contact forces on the objects' surface particles, by the engine's handle.
struct HostObjectForces {
  std::vector<std::uint32_t> handle;
  std::vector<Vec4> force;  // xyz: N; w: fluid particles in contact
};

// Leak tracking, by fluid particle id.
struct HostContainment {
  std::vector<std::int32_t> containerById;
  std::vector<std::uint32_t> insideById;
  std::vector<Vec4> firstExitById;
};

// What the next step reads of the fluid, in the engine's order (the order decides how the next
// sort breaks ties, so a state put back in it steps on byte for byte): Simulation::saveState.
struct HostFluidState {
  HostParticles particles;         // the density is state with continuity density
  std::vector<Vec4> warmStart;     // empty unless the incompressible solver has run
  std::vector<Vec4> externalById;  // empty when unused
  std::vector<std::uint64_t> drainedByOutlet;
  bool densityIsState = false;
  // The neighbours each particle's last density pass listed (fluid::kNeighborOverflow: too many
  // to list): its work, by which a distributed run balances its processes. Not state: a state
  // put back leaves it out.
  std::vector<std::uint32_t> neighbours;
};

// A distributed run's ghost refresh: the density pass's result in the engine's order, and
// where the last buildGrid took each row from: row j held, before it, row gridOrder[j] of the
// state as uploaded.
struct HostDensities {
  std::vector<float> density;
  std::vector<std::uint32_t> gridOrder;
};

struct HostWalls {
  std::vector<std::uint32_t> id;
  std::vector<Vec4> position;  // w: volume
};

// The fluid's stages of a step, in order (the solvers' stage lists, sim/*_step.cpp).
class FluidStages {
 public:
  virtual ~FluidStages() = default;
  virtual std::size_t buildGrid() = 0;  // returns the particles removed
  virtual void computeDensityAndPressure() = 0;
  // From now on the density is state, integrated from its rate of change (continuity): the
  // density pass keeps it, buildGrid reorders it. It starts from `byId`, the density the
  // sampling meant (a kernel sum reads low at the free surface, and that deficit would stay).
  virtual void keepDensity(const std::vector<float>& byId) = 0;
  // With the density kept: after the density pass, ρ += dt Dρ/Dt over the last step's dt
  // (fluid/integrate_density.hpp), and pressure from it.
  virtual void integrateDensity(float dt) = 0;
  virtual void computeForces() = 0;
  // The incompressible solver (DFSPH): its records at this step's positions, after the density
  // pass; then each solve corrects the velocity (NoDivergence, first: it also finds the
  // factors) or the acceleration (RestDensity, after the other forces, over the step dt).
  virtual void prepareSolver() = 0;
  virtual fluid::SolverReport solve(const fluid::SolverSettings& settings,
                                    fluid::SolverTarget target, float dt) = 0;
  // The position solver (PBF): after the density pass at the positions integrate predicted,
  // corrects them over the substep dt and sets the velocity the correction implies; then XSPH
  // smooths the velocities (fluid/pbf_solve.hpp).
  virtual fluid::SolverReport solvePositions(const fluid::PbfSettings& settings, float dt) = 0;
  virtual void smoothVelocities(float coefficient) = 0;
  // Flow in: before integrate, the fluid just past each emitter takes its velocity.
  virtual void driveInflow(const fluid::InflowZones& zones) = 0;
  virtual std::size_t integrate(float dt) = 0;  // returns the particles clamped
  // Flow in: new particles, their ids firstId, firstId + 1, ... (after the walls' and the
  // objects'), at rest density, to be sorted in by the next buildGrid.
  virtual void addParticles(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                            std::uint32_t firstId) = 0;
  // Flow out: the particles each outlet has removed since the start (buildGrid removes them).
  virtual std::vector<std::uint64_t> drainedByOutlet() const = 0;
  // x, y, z, 0 per fluid particle id; empty removes the external accelerations.
  virtual void setExternalAcceleration(const std::vector<Vec4>& byId) = 0;
  // New values for the next steps (Simulation::setLiveParameters); the particles stay.
  virtual void setParameters(const fluid::FluidParameters& params) = 0;
  // A distributed run (sim/exchange_particles.cpp): from the next buildGrid on, the grid is
  // shared by the processes (fluid::Grid::shared), spanning [lo, hi], the bounds of every
  // process's particles; and after the density pass, the rows of ghosts take the density
  // their owners computed (pressure following).
  virtual void shareGrid(Vec3 lo, Vec3 hi) = 0;
  virtual void overwriteDensity(const std::vector<std::uint32_t>& rows,
                                const std::vector<float>& density) = 0;
};

// What the time-step guard reads of the fluid (sim/time_step_guard.cpp).
class FluidMeasures {
 public:
  virtual ~FluidMeasures() = default;
  virtual fluid::StepMeasures measureStep() = 0;
  virtual fluid::BadParticle findBadParticle(float maxDensityError) const = 0;
};

// The fluid's side of the interaction with objects (Meteer 2011, §7; sim/object_coupling.cpp).
class FluidObjectSide {
 public:
  virtual ~FluidObjectSide() = default;
  // A new publication of the objects' surface particles; returns their largest speed.
  virtual float setObjectSurface(const ObjectSurface& surface,
                                 const interaction::InteractionParameters& params) = 0;
  // Adds the contact forces to the fluid's accelerations; returns the pairs in contact.
  virtual std::size_t computeContacts(const interaction::InteractionParameters& params) = 0;
  // With boundary coupling, after the density solve: the pressure's reactions on the objects'
  // particles, added to the forces downloadObjectForces gives.
  virtual void addBoundaryForces() = 0;
  // The same under the position solver, after its solve over the substep dt: the reactions of
  // the density constraints' push, and of the viscous force.
  virtual void addConstraintReactions(float dt) = 0;
  virtual HostObjectForces downloadObjectForces() const = 0;
  // Which object holds each fluid particle (-1: none), by id; all start inside.
  virtual void setContainers(const std::vector<std::int32_t>& byId) = 0;
  virtual HostContainment downloadContainment() const = 0;
  // Leak tracking as downloadContainment gave it (a saved simulation state).
  virtual void uploadContainment(const HostContainment& state) = 0;
};

// What frames, statistics, probes, saved states and renderers read of the fluid
// (sim/simulation_output.cpp, simulation_state.cpp).
class FluidOutputs {
 public:
  virtual ~FluidOutputs() = default;
  // Outside the step: |∇c| at the present positions into acceleration.w (the surface flags),
  // from the last density pass's neighbours.
  virtual void measureSurface() = 0;
  // Copies the fluid out as it is now, and waits for the copy.
  HostParticles download() const { return beginDownload()->take(); }
  // Copies the fluid out as it is now without waiting: the GPU snapshots its arrays and copies
  // them to pinned host memory while the next steps run; the CPU copies at once.
  virtual std::unique_ptr<PendingParticles> beginDownload() const = 0;
  virtual HostWalls downloadWalls() const = 0;
  virtual HostDensities downloadDensities() const = 0;
  // The fluid's arrays in place where they are host memory; empty otherwise.
  virtual FluidView hostView() const = 0;
  // The fluid's state between steps, and back (the particle counts may differ from now's).
  virtual HostFluidState downloadState() const = 0;
  virtual void uploadState(const HostFluidState& state) = 0;
  // Which wall particles wallForces measures (1) and which it leaves at zero, in
  // downloadWalls' order: only the walls a probe reads pay the pass.
  virtual void watchWalls(const std::vector<std::uint8_t>& watched) = 0;
  // The fluid's force on each watched wall particle this step, in downloadWalls' order
  // (fluid/wall_forces.hpp): after the forces and the solves, before integrate.
  virtual std::vector<Vec4> wallForces() = 0;
  // The fluid's sums at each point (the probes, core/probe.hpp), as a frame taken now shows it.
  virtual std::vector<PointSums> samplePoints(const std::vector<Vec3>& points) = 0;
  // The fluid into arrays in this backend's memory, for a renderer (target checked by the
  // caller). On the GPU the writes are queued on the default stream.
  virtual void writeForDrawing(const FluidDrawTarget& target, float surfaceThreshold) const = 0;
};

// The fluid state and its stages on one backend, seen by concern.
class FluidEngine : public FluidStages,
                    public FluidMeasures,
                    public FluidObjectSide,
                    public FluidOutputs {
 public:
  virtual const char* backendName() const = 0;
  virtual std::size_t fluidCount() const = 0;
  virtual std::size_t wallCount() const = 0;
};

struct EngineSetup {
  fluid::FluidParameters params;
  fluid::DomainParameters domain;
  std::vector<Vec3> positions;   // fluid, by id
  std::vector<Vec3> velocities;  // fluid, by id
  std::vector<float> densities;  // fluid, by id: at rest as sampled (sampling.hpp)
  std::vector<Vec3> walls;       // wall particles; their ids follow the fluid's
  std::uint32_t neighborStride = 0;
  fluid::NeighborWalk walk = fluid::NeighborWalk::Batched;
};

std::unique_ptr<FluidEngine> makeCpuEngine(const EngineSetup& setup);
// Throws InputError when this build has no CUDA backend or no GPU is usable.
std::unique_ptr<FluidEngine> makeCudaEngine(const EngineSetup& setup, int device);

}  // namespace sph::sim
