// Setting a simulation up: the scene checked and calibrated, the walls, the objects' engine,
// the fluid sampled around them, the engine on its backend, the state of frame 0.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "sim/object_clearance.hpp"
#include "sim/sampling.hpp"
#include "sim/scene_size.hpp"
#include "sim/simulation_impl.hpp"
#include "sph/core/contact.hpp"
#include "sph/devices.hpp"

namespace sph {

Simulation::Impl::Impl(const Scene& s, const SimulationOptions& options)
    : scene(scene::validateScene(s)), threads(checkedThreads(options.threads)), inflow(scene) {
  const backend::ScopedThreadCount passThreads(threads);
  backend::requireCompiledInstructionSet();
  sim::refuseIfTooLarge(scene, sim::availableBytes());  // before anything large is made
  calibration = sim::calibrate(scene);
  const sim::Walls walls(scene);
  sim::EngineSetup setup = sim::engineSetup(scene, calibration, walls);
  if (options.neighborListLength > 0) setup.neighborStride = options.neighborListLength;
  setup.walk = options.cpuPasses == CpuPasses::Batched ? fluid::NeighborWalk::Batched
                                                       : fluid::NeighborWalk::OneAtATime;
  params = setup.params;
  clock.dt = calibration.initialDt;
  std::optional<objects::ObjectWorld> world;
  coupling.constraintReactions = scene.fluid.solver == FluidSolver::Pbf;
  // Under Bullet the scene's objects are the attached engine's (sph/bullet_engine.hpp).
  if (!scene.objects.empty() && scene.objectEngine.type == ObjectEngineKind::Builtin) {
    objects::WorldSettings settings = sim::worldSettings(scene, calibration);
    // Objects rest on the walls that hold the fluid; they meet the walls across a periodic
    // face through their own images, not the walls' (which follow the walls' particles).
    settings.staticParticles.assign(
        setup.walls.begin(), setup.walls.begin() + std::ptrdiff_t(walls.firstParticle().back()));
    settings.staticRadius = static_cast<float>(0.5 * scene.fluid.spacing);
    world.emplace(scene.objects, settings);
    coupling.params = sim::interactionParameters(scene, calibration);
    sim::ObjectCoupling::checkContactReach(*world, coupling.params, params.h, scene.sourcePath);
    checkPeriodicExtent(*world);
  }

  sampleFluid(setup, walls, world ? &*world : nullptr);
  counts.initialFluid = setup.positions.size();
  engine =
      useCuda(options) ? sim::makeCudaEngine(setup, options.device) : sim::makeCpuEngine(setup);

  calibration.fluidParticles = counts.initialFluid;
  calibration.boundaryParticles = engine->wallCount();
  if (world) {
    calibration.objectParticles = world->particles().size();
    engine->setContainers(containers(*world, setup.positions));
    coupling.fluidForceOnObject.assign(world->objectCount(), Vec3{0, 0, 0});
    coupling.contactForceOnObject.assign(world->objectCount(), Vec3{0, 0, 0});
    coupling.objects = std::make_unique<sim::ObjectRunner>(
        std::move(*world), scene.objectEngine.rate, scene.objectEngine.ownThread);
  }
  if (sim::Outputs::probesWallForces(scene))
    outputs.mapWallParticles(*engine, walls, scene, counts.initialFluid);
  inflow.nextId =
      std::uint32_t(counts.initialFluid + engine->wallCount() + calibration.objectParticles);
  // Density and pressure of the initial state, so stats and frame 0 are meaningful.
  counts.removed += engine->buildGrid();
  engine->computeDensityAndPressure();
  if (params.continuityDensity) engine->keepDensity(setup.densities);
  // The position solver's first substep predicts with the forces (gravity, at least).
  if (scene.fluid.solver == FluidSolver::Pbf) engine->computeForces();
  outputs.probes = std::make_unique<sim::ProbeSampler>(scene, scene.fluid.spacing);
  sampleProbes();
  stages = stageList();
}

void Simulation::Impl::sampleFluid(sim::EngineSetup& setup, const sim::Walls& walls,
                                   const objects::ObjectWorld* world) const {
  for (const auto& block : scene.fluid.blocks) {
    auto points = sim::sampleBlock(block.box, scene.fluid.spacing);
    walls.removeOverlap(points);
    if (!block.inside.empty()) keepInside(points, block.inside, world);
    if (world) {
      const int container = block.inside.empty() ? -1 : int(objectIndex(block.inside));
      sim::removeObjectOverlap(
          points, *world,
          [&](float radius) { return interaction::contactReach(coupling.params, radius); },
          container);
    }
    if (block.hydrostatic)
      sim::compressHydrostatically(points, block.box, scene.gravity, calibration.soundSpeed);
    const std::vector<float> rho =
        sim::restingDensities(points, block.box, block.hydrostatic, scene.gravity,
                              calibration.soundSpeed, scene.fluid.restDensity);
    setup.densities.insert(setup.densities.end(), rho.begin(), rho.end());
    const Vec3 v{float(block.velocity[0]), float(block.velocity[1]), float(block.velocity[2])};
    const Vec3 w{float(block.angularVelocity[0]), float(block.angularVelocity[1]),
                 float(block.angularVelocity[2])};
    const Vec3 centre{float(0.5 * (block.box.min[0] + block.box.max[0])),
                      float(0.5 * (block.box.min[1] + block.box.max[1])),
                      float(0.5 * (block.box.min[2] + block.box.max[2]))};
    setup.positions.insert(setup.positions.end(), points.begin(), points.end());
    for (const Vec3& p : points) {
      const Vec3 r = p - centre;  // v + ω × r
      setup.velocities.push_back(
          v + Vec3{w.y * r.z - w.z * r.y, w.z * r.x - w.x * r.z, w.x * r.y - w.y * r.x});
    }
  }
}

void Simulation::Impl::keepInside(std::vector<Vec3>& points, const std::string& name,
                                  const objects::ObjectWorld* world) const {
  const std::size_t o = objectIndex(name);
  const float margin = interaction::contactReach(
      coupling.params, world->particles().radius[world->info(o).firstParticle]);
  points.erase(std::remove_if(points.begin(), points.end(),
                              [&](Vec3 p) { return !world->interiorContains(o, p, margin); }),
               points.end());
}

std::size_t Simulation::Impl::objectIndex(const std::string& name) const {
  for (std::size_t o = 0; o < scene.objects.size(); ++o)
    if (scene.objects[o].name == name) return o;
  throw InputError(scene.sourcePath + ": fluid.blocks[].inside: no object is named '" + name + "'");
}

std::vector<std::int32_t> Simulation::Impl::containers(const objects::ObjectWorld& world,
                                                       const std::vector<Vec3>& positions) {
  std::vector<std::int32_t> byId(positions.size(), -1);
  for (std::size_t o = 0; o < world.objectCount(); ++o) {
    if (!world.enclosesVolume(o)) continue;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      if (byId[i] < 0 && world.interiorContains(o, positions[i], 0.0f))
        byId[i] = static_cast<std::int32_t>(o);
    }
  }
  return byId;
}

void Simulation::Impl::checkPeriodicExtent(const objects::ObjectWorld& world) const {
  const objects::PeriodicSpace& space = world.periodicSpace();
  const objects::ParticleState& particles = world.particles();
  const double periods[3] = {space.length.x, space.length.y, space.length.z};
  for (std::size_t o = 0; o < world.objectCount() && space.any(); ++o) {
    const objects::ObjectInfo info = world.info(o);
    for (int a = 0; a < 3; ++a) {
      if (!space.periodic[a]) continue;
      double lo = 1e300, hi = -1e300;
      for (std::size_t i = info.firstParticle; i < info.firstParticle + info.particleCount; ++i) {
        const Vec3 x = particles.position[i];
        const double v = a == 0 ? x.x : a == 1 ? x.y : x.z;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      const double most = periods[a] - 2.0 * scene.fluid.supportRatio * scene.fluid.spacing;
      if (hi - lo > most)  // the extent of float positions, to the micrometre
        throw InputError(scene.sourcePath + ": objects[" + std::to_string(o) +
                         "]: expected the object to span at most the domain's period along " +
                         "periodic axis " + "xyz"[a] + " less two support radii (" +
                         formatNumber(most) + " m), got " +
                         formatNumber(std::round((hi - lo) * 1e6) / 1e6) + " m");
    }
  }
}

int Simulation::Impl::checkedThreads(int threads) {
  if (threads < 0 || threads > kMaxThreads)
    throw std::invalid_argument(
        "SimulationOptions::threads: expected 0 (the caller's setting) to " +
        std::to_string(kMaxThreads) + ", got " + std::to_string(threads));
  return threads;
}

bool Simulation::Impl::useCuda(const SimulationOptions& options) {
  if (options.backend == Backend::Cuda) return true;
  return options.backend == Backend::Auto && !queryGpus().devices.empty();
}

}  // namespace sph
