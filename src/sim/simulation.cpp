#include "sph/simulation.hpp"

#include <stdexcept>
#include <string>

#include "backend/cpu_parallel.hpp"
#include "sim/simulation_impl.hpp"

namespace sph {

Simulation::Simulation(const Scene& scene, const SimulationOptions& options)
    : impl_(std::make_unique<Impl>(scene, options)) {}
Simulation::~Simulation() = default;

// The step is its solver's list of stages (sim/wcsph_step.cpp, sim/dfsph_step.cpp), each
// timed into its StepProfile bucket.
void Simulation::step(double until) {
  Impl& s = *impl_;
  if (s.scene.objectEngine.type == ObjectEngineKind::Bullet && !s.scene.objects.empty() &&
      !s.coupling.externalExchange)
    throw std::logic_error(s.scene.sourcePath +
                           ": object_engine.type is \"bullet\": attach its Bullet world before "
                           "stepping (sph::BulletEngine::forScene, sph/bullet_engine.hpp)");
  const backend::ScopedThreadCount passThreads(s.threads);
  s.clock.until = until;
  s.profile = StepProfile{};
  for (const Impl::Stage& stage : s.stages)
    s.profile.*stage.bucket += detail::timedMs([&] { (s.*stage.run)(); });
  ++s.clock.steps;
}

std::vector<std::string> Simulation::stageNames() const {
  std::vector<std::string> names;
  for (const Impl::Stage& stage : impl_->stages) names.emplace_back(stage.name);
  return names;
}

void Simulation::attachObjectEngine(std::shared_ptr<ObjectExchange> exchange) {
  Impl& s = *impl_;
  if (!exchange) throw std::invalid_argument("attachObjectEngine: expected an exchange, got null");
  if (s.coupling.objects)
    throw std::logic_error("attachObjectEngine: " + s.scene.sourcePath +
                           " has objects of its own, moved by the built-in engine");
  if (s.coupling.externalExchange)
    throw std::logic_error("attachObjectEngine: an object engine is attached already");
  // The contact with the attached objects is calibrated as for a scene's own objects.
  Calibration calibration = sim::calibrate(s.scene, /*attachedEngine=*/true);
  calibration.fluidParticles = s.calibration.fluidParticles;
  calibration.boundaryParticles = s.calibration.boundaryParticles;
  calibration.initialDt = s.calibration.initialDt;
  s.calibration = calibration;
  s.coupling.params = sim::interactionParameters(s.scene, s.calibration);
  s.coupling.externalExchange = std::move(exchange);
  s.coupling.seenPublication = 0;
  s.stages = s.stageList();  // now with the objects' stages
}

void Simulation::containFluid(std::int32_t object, const std::vector<std::uint32_t>& ids) {
  Impl& s = *impl_;
  if (!s.coupling.externalExchange)
    throw std::logic_error("containFluid: attach an object engine first (attachObjectEngine)");
  if (s.clock.steps != 0) throw std::logic_error("containFluid: call it before the first step");
  if (object < 0)
    throw std::invalid_argument("containFluid: expected an object id >= 0, got " +
                                std::to_string(object));
  const std::size_t n = s.counts.initialFluid;
  for (std::uint32_t id : ids)
    if (id >= n)
      throw std::invalid_argument("containFluid: " + std::to_string(id) +
                                  " is no fluid particle's id (there are " + std::to_string(n) +
                                  ")");
  std::vector<std::int32_t>& containers = s.coupling.externalContainers;
  if (containers.empty()) containers.assign(n, -1);
  for (std::uint32_t id : ids) containers[id] = object;
  s.engine->setContainers(containers);
}

void Simulation::setExternalAcceleration(const std::vector<float>& byId) {
  if (impl_->ranks)
    throw std::logic_error("setExternalAcceleration: not yet for a run across processes");
  if (byId.empty()) {
    impl_->engine->setExternalAcceleration({});
    return;
  }
  const std::size_t n = impl_->counts.initialFluid;
  if (byId.size() != 3 * n)
    throw std::invalid_argument("setExternalAcceleration: expected 3 × " + std::to_string(n) +
                                " values (x, y, z per fluid particle), got " +
                                std::to_string(byId.size()));
  std::vector<Vec4> accelerations(n);
  for (std::size_t i = 0; i < n; ++i)
    accelerations[i] = Vec4{byId[3 * i], byId[3 * i + 1], byId[3 * i + 2], 0.0f};
  impl_->engine->setExternalAcceleration(accelerations);
}

void Simulation::advanceTo(double t) {
  while (impl_->clock.time < t) step(t);
}

double Simulation::time() const {
  return impl_->clock.time;
}
std::uint64_t Simulation::stepCount() const {
  return impl_->clock.steps;
}
double Simulation::lastDt() const {
  return impl_->clock.dt;
}
std::uint64_t Simulation::removedCount() const {
  return impl_->counts.removed;
}
std::uint64_t Simulation::emittedCount() const {
  std::uint64_t n = 0;
  const sim::Emitters& emitters = impl_->inflow.emitters;
  for (std::size_t k = 0; k < emitters.size(); ++k) n += emitters.emitted(k);
  return n;
}
std::vector<FlowStats> Simulation::emitterStats() const {
  const Impl& s = *impl_;
  const sim::Emitters& emitters = s.inflow.emitters;
  std::vector<FlowStats> out;
  for (std::size_t k = 0; k < emitters.size(); ++k) {
    const std::uint64_t n = emitters.emitted(k);
    out.push_back({emitters.name(k), n, double(n) * s.calibration.mass, emitters.particleRate(k)});
  }
  return out;
}
std::vector<FlowStats> Simulation::outletStats() const {
  const Impl& s = *impl_;
  const std::vector<std::uint64_t> drained = s.engine->drainedByOutlet();
  std::vector<FlowStats> out;
  for (std::size_t k = 0; k < s.scene.outlets.size(); ++k)
    out.push_back({s.scene.outlets[k].name, drained[k], double(drained[k]) * s.calibration.mass});
  return out;
}
std::uint64_t Simulation::clampedCount() const {
  return impl_->counts.clamped;
}
std::uint64_t Simulation::fluidCount() const {
  return impl_->ranks ? impl_->ranks->owned() : impl_->engine->fluidCount();
}
const char* Simulation::backendName() const {
  return impl_->engine->backendName();
}
const Scene& Simulation::scene() const {
  return impl_->scene;
}
const Calibration& Simulation::calibration() const {
  return impl_->calibration;
}
SolverStats Simulation::lastSolve() const {
  const Impl& s = *impl_;
  SolverStats out;
  if (!s.incompressible()) return out;
  const sim::SolverRecord& r = s.solves;
  out.densityIterations = r.density.iterations;
  out.divergenceIterations = r.divergence.iterations;
  out.densityError = r.density.averageError;
  out.largestDensityError = r.density.largestError;
  out.divergenceError = r.divergence.averageError;
  out.converged = r.density.converged && r.divergence.converged;
  return out;
}
const std::vector<std::string>& Simulation::probeColumns() const {
  return impl_->outputs.probes->columns();
}
std::vector<ProbeRow> Simulation::takeProbeRows() {
  return impl_->outputs.probes->take();
}
const StepProfile& Simulation::lastProfile() const {
  return impl_->profile;
}

}  // namespace sph
