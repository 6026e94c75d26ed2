// FluidEngine for backend B: the particle arrays in B's memory and the stages run on them.
// Included by cpu_engine.cpp (g++) and cuda_engine.cu (nvcc) only.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "fluid/drive_inflow.hpp"
#include "fluid/measure_surface.hpp"
#include "fluid/overwrite_density.hpp"
#include "fluid/stages.hpp"
#include "fluid/write_for_drawing.hpp"
#include "interaction/stages.hpp"
#include "sim/fluid_engine.hpp"

namespace sph::sim {

// Pinned host memory and snapshots for downloads in flight (cuda_engine.cu); none on the CPU.
class DownloadStaging;

template <class B>
HostParticles downloadNow(const fluid::FluidParticles<B>& fluid) {
  const std::size_t n = fluid.count;
  HostParticles h;
  h.id.resize(n);
  h.position.resize(n);
  h.velocity.resize(n);
  h.density.resize(n);
  h.pressure.resize(n);
  h.acceleration.resize(n);
  B::download(fluid.id, h.id.data(), n);
  B::download(fluid.position, h.position.data(), n);
  B::download(fluid.velocity, h.velocity.data(), n);
  B::download(fluid.density, h.density.data(), n);
  B::download(fluid.pressure, h.pressure.data(), n);
  B::download(fluid.acceleration, h.acceleration.data(), n);
  return h;
}

// The CPU's memory is the host's: the copy is made at once. The CUDA backend specialises this
// (cuda_engine.cu).
template <class B>
std::unique_ptr<PendingParticles> beginParticleDownload(const fluid::FluidParticles<B>& fluid,
                                                        std::shared_ptr<DownloadStaging>&) {
  return std::make_unique<ReadyParticles>(downloadNow(fluid));
}

template <class B>
class EngineImpl final : public FluidEngine {
 public:
  explicit EngineImpl(const EngineSetup& setup)
      : params_(setup.params), domain_(setup.domain), walk_(setup.walk) {
    const std::size_t n = setup.positions.size();
    std::vector<Vec4> position(n), velocity(n), zero(n, Vec4{0, 0, 0, 0});
    std::vector<std::uint32_t> id(n);
    for (std::size_t i = 0; i < n; ++i) {
      position[i] = makeVec4(setup.positions[i]);
      velocity[i] = makeVec4(setup.velocities[i]);
      id[i] = static_cast<std::uint32_t>(i);
    }
    fluid_.count = n;
    B::upload(fluid_.position, position.data(), n);
    B::upload(fluid_.velocity, velocity.data(), n);
    B::upload(fluid_.acceleration, zero.data(), n);
    B::upload(fluid_.id, id.data(), n);
    fluid_.density.resize(n);
    fluid_.pressure.resize(n);
    fluid_.neighborStride = setup.neighborStride;
    resizeWorkArrays(n);
    drained_.assign(domain_.outlets.count, 0);
    grid_.cellSize = params_.h;
    fluid::prepareBoundary(boundary_, setup.walls, static_cast<std::uint32_t>(n), params_);
  }

  const char* backendName() const override { return B::kName; }
  std::size_t fluidCount() const override { return fluid_.count; }
  std::size_t wallCount() const override { return boundary_.count; }

  std::size_t buildGrid() override {
    if (domain_.outlets.count != 0) {
      const auto inOutlets = fluid::countInOutlets(fluid_, domain_.outlets);
      for (std::size_t k = 0; k < drained_.size(); ++k) drained_[k] += inOutlets.n[k];
    }
    return fluid::buildGrid(fluid_, grid_, domain_);
  }
  std::vector<std::uint64_t> drainedByOutlet() const override { return drained_; }
  void driveInflow(const fluid::InflowZones& zones) override { fluid::driveInflow(fluid_, zones); }

  // Appends to the state arrays through the host: emitters add a layer every few steps, and
  // the copies cost far less than a step.
  void addParticles(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                    std::uint32_t firstId) override {
    const std::size_t n = fluid_.count;
    const std::size_t added = positions.size();
    if (added == 0) return;
    const std::size_t total = n + added;
    const auto extend = [&](auto& buffer, auto fill) {
      using T = decltype(fill(std::size_t{0}));
      std::vector<T> host(total);
      B::download(buffer, host.data(), n);
      for (std::size_t k = 0; k < added; ++k) host[n + k] = fill(k);
      B::upload(buffer, host.data(), total);
    };
    extend(fluid_.position, [&](std::size_t k) { return makeVec4(positions[k]); });
    extend(fluid_.velocity, [&](std::size_t k) { return makeVec4(velocities[k]); });
    extend(fluid_.acceleration, [](std::size_t) { return Vec4{0, 0, 0, 0}; });
    extend(fluid_.id, [&](std::size_t k) { return std::uint32_t(firstId + k); });
    extend(fluid_.density, [&](std::size_t) { return params_.restDensity; });
    extend(fluid_.pressure, [](std::size_t) { return 0.0f; });
    if (fluid_.warmStart.size() != 0)
      extend(fluid_.warmStart, [](std::size_t) { return Vec4{0, 0, 0, 0}; });
    fluid_.count = total;
    resizeWorkArrays(total);
    growByIdArrays(firstId + added);
  }
  void computeDensityAndPressure() override {
    fluid::computeDensityAndPressure(fluid_, grid_, boundary_, objectBoundary_, params_, walk_);
  }
  void computeForces() override {
    fluid::computeForces(fluid_, grid_, boundary_, objectBoundary_, params_, walk_);
  }
  void prepareSolver() override { fluid::prepareSolver(fluid_); }
  void integrateDensity(float dt) override {
    fluid::integrateDensity(fluid_, grid_, boundary_, params_, dt, walk_);
  }
  void keepDensity(const std::vector<float>& byId) override {
    const std::size_t n = fluid_.count;
    std::vector<std::uint32_t> id(n);
    std::vector<float> density(n);
    B::download(fluid_.id, id.data(), n);
    for (std::size_t i = 0; i < n; ++i) density[i] = byId[id[i]];
    B::upload(fluid_.density, density.data(), n);
    fluid_.densityIsState = true;
  }
  fluid::SolverReport solve(const fluid::SolverSettings& settings, fluid::SolverTarget target,
                            float dt) override {
    return fluid::solve(fluid_, grid_, boundary_, objectBoundary_, params_, settings, target, dt,
                        walk_, coarse_);
  }
  fluid::SolverReport solvePositions(const fluid::PbfSettings& settings, float dt) override {
    return fluid::solvePositions(fluid_, grid_, boundary_, objectBoundary_, params_, settings, dt,
                                 domain_, walk_);
  }
  void smoothVelocities(float coefficient) override {
    fluid::smoothVelocities(fluid_, grid_, boundary_, objectBoundary_, params_, coefficient, walk_);
  }
  fluid::StepMeasures measureStep() override {
    return fluid::measureStep(fluid_, params_.restDensity);
  }
  std::size_t integrate(float dt) override { return fluid::integrate(fluid_, dt, domain_); }
  void measureSurface() override { fluid::measureSurface(fluid_, grid_, boundary_, params_); }

  float setObjectSurface(const ObjectSurface& surface,
                         const interaction::InteractionParameters& params) override {
    return interaction::prepareObjectParticles(objects_, objectBoundary_, surface, params, params_,
                                               domain_.min, domain_.max);
  }
  void addBoundaryForces() override {
    interaction::addBoundaryForces(fluid_, grid_, objectBoundary_, objects_, params_);
  }
  void addConstraintReactions(float dt) override {
    interaction::addConstraintReactions(fluid_, objectBoundary_, objects_, dt);
    interaction::addBoundaryForces(fluid_, grid_, objectBoundary_, objects_, params_,
                                   /*positionSolver=*/true);
  }
  std::size_t computeContacts(const interaction::InteractionParameters& params) override {
    return interaction::computeContacts(fluid_, grid_, objects_, containment_, params);
  }
  HostObjectForces downloadObjectForces() const override {
    HostObjectForces out;
    out.handle.resize(objects_.count);
    out.force.resize(objects_.count);
    B::download(objects_.handle, out.handle.data(), objects_.count);
    B::download(objects_.force, out.force.data(), objects_.count);
    return out;
  }
  void setContainers(const std::vector<std::int32_t>& byId) override {
    const std::size_t n = byId.size();
    std::vector<std::uint32_t> inside(n);
    for (std::size_t k = 0; k < n; ++k) inside[k] = byId[k] >= 0 ? 1u : 0u;
    const std::vector<Vec4> noExit(n, Vec4{0, 0, 0, 0});
    B::upload(containment_.containerById, byId.data(), n);
    B::upload(containment_.insideById, inside.data(), n);
    B::upload(containment_.firstExitById, noExit.data(), n);
  }
  HostContainment downloadContainment() const override {
    HostContainment out;
    const std::size_t n = containment_.containerById.size();
    out.containerById.resize(n);
    out.insideById.resize(n);
    out.firstExitById.resize(n);
    B::download(containment_.containerById, out.containerById.data(), n);
    B::download(containment_.insideById, out.insideById.data(), n);
    B::download(containment_.firstExitById, out.firstExitById.data(), n);
    return out;
  }

  void uploadContainment(const HostContainment& state) override {
    B::upload(containment_.containerById, state.containerById.data(), state.containerById.size());
    B::upload(containment_.insideById, state.insideById.data(), state.insideById.size());
    B::upload(containment_.firstExitById, state.firstExitById.data(), state.firstExitById.size());
  }

  fluid::BadParticle findBadParticle(float maxDensityError) const override {
    return fluid::findBadParticle(fluid_, params_.restDensity, maxDensityError);
  }

  std::unique_ptr<PendingParticles> beginDownload() const override {
    return beginParticleDownload(fluid_, staging_);
  }

  FluidView hostView() const override {
    FluidView v;
    if constexpr (B::kHostMemory) {
      static_assert(sizeof(Vec4) == FluidView::kVectorStride * sizeof(float));
      v.count = fluid_.count;
      v.id = fluid_.id.data();
      v.position = reinterpret_cast<const float*>(fluid_.position.data());
      v.velocity = reinterpret_cast<const float*>(fluid_.velocity.data());
      v.density = fluid_.density.data();
      v.pressure = fluid_.pressure.data();
    }
    return v;
  }
  HostWalls downloadWalls() const override {
    HostWalls w;
    w.id.resize(boundary_.count);
    w.position.resize(boundary_.count);
    B::download(boundary_.id, w.id.data(), boundary_.count);
    B::download(boundary_.position, w.position.data(), boundary_.count);
    return w;
  }
  HostFluidState downloadState() const override {
    const std::size_t n = fluid_.count;
    HostFluidState s;
    s.particles = downloadNow(fluid_);
    const auto copy = [](const auto& buffer, auto& host, std::size_t count) {
      host.resize(count);
      B::download(buffer, host.data(), count);
    };
    copy(fluid_.warmStart, s.warmStart, fluid_.warmStart.size() != 0 ? n : 0);
    copy(fluid_.externalById, s.externalById, fluid_.externalById.size());
    copy(fluid_.neighborCount, s.neighbours, fluid_.neighborCount.size() >= n ? n : 0);
    s.drainedByOutlet = drained_;
    s.densityIsState = fluid_.densityIsState;
    return s;
  }
  void uploadState(const HostFluidState& s) override {
    const HostParticles& p = s.particles;
    const std::size_t n = p.id.size();
    fluid_.count = n;
    B::upload(fluid_.id, p.id.data(), n);
    B::upload(fluid_.position, p.position.data(), n);
    B::upload(fluid_.velocity, p.velocity.data(), n);
    B::upload(fluid_.acceleration, p.acceleration.data(), n);
    B::upload(fluid_.density, p.density.data(), n);
    B::upload(fluid_.pressure, p.pressure.data(), n);
    if (s.warmStart.empty())
      fluid_.warmStart.resize(0);
    else
      B::upload(fluid_.warmStart, s.warmStart.data(), n);
    if (s.externalById.empty())
      fluid_.externalById.resize(0);
    else
      B::upload(fluid_.externalById, s.externalById.data(), s.externalById.size());
    drained_ = s.drainedByOutlet;
    fluid_.densityIsState = s.densityIsState;
    resizeWorkArrays(n);
  }
  void watchWalls(const std::vector<std::uint8_t>& watched) override {
    B::upload(watchedWall_, watched.data(), watched.size());
  }
  std::vector<Vec4> wallForces() override {
    wallForce_.resize(boundary_.count);
    fluid::wallForces(fluid_, grid_, boundary_, params_, watchedWall_.data(), wallForce_.data());
    std::vector<Vec4> out(boundary_.count);
    B::download(wallForce_, out.data(), boundary_.count);
    return out;
  }
  std::vector<PointSums> samplePoints(const std::vector<Vec3>& points) override {
    const std::size_t n = points.size();
    std::vector<Vec4> at(n);
    for (std::size_t k = 0; k < n; ++k) at[k] = makeVec4(points[k]);
    B::upload(probePoints_, at.data(), n);
    probeSums_.resize(n);
    fluid::samplePoints(fluid_, grid_, params_, probePoints_.data(), n, probeSums_.data());
    std::vector<PointSums> out(n);
    B::download(probeSums_, out.data(), n);
    return out;
  }

  void writeForDrawing(const FluidDrawTarget& target, float surfaceThreshold) const override {
    fluid::writeForDrawing(fluid_, reinterpret_cast<Vec4*>(target.position), target.value,
                           target.id, target.quantity, surfaceThreshold);
  }

  void setParameters(const fluid::FluidParameters& params) override { params_ = params; }

  void shareGrid(Vec3 lo, Vec3 hi) override {
    grid_.shared = true;
    grid_.sharedLo = lo;
    grid_.sharedHi = hi;
  }
  void overwriteDensity(const std::vector<std::uint32_t>& rows,
                        const std::vector<float>& density) override {
    fluid::overwriteDensity(fluid_, rows, density, params_, rowScratch_, densityScratch_);
  }
  HostDensities downloadDensities() const override {
    const std::size_t n = fluid_.count;
    HostDensities out;
    out.density.resize(n);
    out.gridOrder.resize(n);
    B::download(fluid_.density, out.density.data(), n);
    B::download(fluid_.order, out.gridOrder.data(), n);
    return out;
  }

  void setExternalAcceleration(const std::vector<Vec4>& byId) override {
    if (byId.empty()) {
      fluid_.externalById.resize(0);
      return;
    }
    B::upload(fluid_.externalById, byId.data(), byId.size());
  }

 private:
  // The arrays every step writes before it reads them, for n particles.
  void resizeWorkArrays(std::size_t n) {
    for (auto* b : {&fluid_.scratch4, &fluid_.pressureState}) b->resize(n);
    for (auto* b : {&fluid_.cell, &fluid_.order, &fluid_.scratchId, &fluid_.neighborCount})
      b->resize(n);
    fluid_.scratchDensity.resize(n);
    fluid_.neighbors.resize(n * fluid_.neighborStride);
  }
  // The arrays indexed by particle id, to hold ids below `ids`: new particles have no external
  // acceleration and no container.
  void growByIdArrays(std::size_t ids) {
    const auto grow = [&](auto& buffer, auto value) {
      const std::size_t had = buffer.size();
      if (had == 0 || had >= ids) return;
      std::vector<decltype(value)> host(ids, value);
      B::download(buffer, host.data(), had);
      B::upload(buffer, host.data(), ids);
    };
    grow(fluid_.externalById, Vec4{0, 0, 0, 0});
    grow(containment_.containerById, std::int32_t{-1});
    grow(containment_.insideById, std::uint32_t{0});
    grow(containment_.firstExitById, Vec4{0, 0, 0, 0});
  }

  fluid::FluidParameters params_;
  fluid::DomainParameters domain_;
  fluid::NeighborWalk walk_;
  fluid::FluidParticles<B> fluid_;
  mutable std::shared_ptr<DownloadStaging> staging_;  // made on the first download
  fluid::BoundaryParticles<B> boundary_;
  fluid::Grid<B> grid_;
  fluid::CoarsePressure coarse_;  // the density solve's coarse level, host memory
  interaction::ObjectParticles<B> objects_;
  fluid::BoundaryParticles<B> objectBoundary_;  // the objects', with boundary coupling
  interaction::ContainmentState<B> containment_;
  typename B::template Buffer<Vec4> probePoints_;
  typename B::template Buffer<Vec4> wallForce_;
  typename B::template Buffer<std::uint8_t> watchedWall_;
  typename B::template Buffer<PointSums> probeSums_;
  typename B::template Buffer<std::uint32_t> rowScratch_;  // overwriteDensity's
  typename B::template Buffer<float> densityScratch_;
  std::vector<std::uint64_t> drained_;  // by outlet, since the start
};

}  // namespace sph::sim
