// The fluid's side of the coupling with objects (Meteer 2011, §7): the engine's surface
// particles in, the forces on them out, and the engine's step handed over.
#include "sim/simulation_impl.hpp"

namespace sph {

void Simulation::Impl::receiveObjects() {
  if (!objects) {
    exchange().readIfNew(seenPublication, [&](const ObjectSurface& surface) {
      checkExternalSurface(surface);
      objectMaxSpeed = engine->setObjectSurface(surface, interactionParams);
      externalSurface = surface;
    });
    return;
  }
  objects->wait();
  objects->exchange().readIfNew(seenPublication, [&](const ObjectSurface& surface) {
    objectMaxSpeed = engine->setObjectSurface(surface, interactionParams);
  });
  // Read here, where the engine is known to be idle: the probes sample after the fluid's
  // step, while the engine may be running its own.
  for (std::size_t o = 0; o < contactForceOnObject.size(); ++o)
    contactForceOnObject[o] = objects->world().contactForce(o);
}

void Simulation::Impl::checkExternalSurface(const ObjectSurface& surface) {
  const auto refuse = [&](const std::string& what) {
    throw std::invalid_argument("attached object engine: its publication at t = " +
                                formatNumber(surface.time) + " s " + what);
  };
  externalObjectOfHandle.assign(exchange().handleCount(), -1);
  std::int32_t objectCount = 0;
  for (std::size_t k = 0; k < surface.size(); ++k) {
    const float reach = interaction::contactReach(interactionParams, surface.position[k].w);
    if (!(reach <= params.h))
      refuse("has a particle of radius " + formatNumber(surface.position[k].w) +
             " m whose contact reach, " + formatNumber(reach) +
             " m, passes the fluid's support radius h = " + formatNumber(params.h) + " m");
    externalObjectOfHandle[surface.handle[k]] = surface.object[k];
    objectCount = std::max(objectCount, surface.object[k] + 1);
  }
  if (fluidForceOnObject.size() < std::size_t(objectCount))
    fluidForceOnObject.resize(std::size_t(objectCount), Vec3{0, 0, 0});
}

void Simulation::Impl::collectObjectForces() {
  if (objectsAsBoundary()) engine->addBoundaryForces();
  objectForces = engine->downloadObjectForces();
  if (objectsAsBoundary()) {  // the pairs within h that pushed
    contactPairs = 0;
    for (const Vec4& f : objectForces.force) contactPairs += std::uint64_t(f.w);
  }
}

void Simulation::Impl::advanceObjects() {
  const std::size_t n = objectForces.handle.size();
  exchange().depositForces(objectForces.handle.data(), objectForces.force.data(), n, dt);
  std::fill(fluidForceOnObject.begin(), fluidForceOnObject.end(), Vec3{0, 0, 0});
  if (!objects) {  // the attached engine takes the forces and steps when it will
    for (std::size_t k = 0; k < n; ++k)
      fluidForceOnObject[externalObjectOfHandle[objectForces.handle[k]]] +=
          xyz(objectForces.force[k]);
    return;
  }
  const objects::ParticleState& particles = objects->world().particles();
  for (std::size_t k = 0; k < n; ++k)
    fluidForceOnObject[particles.object[objectForces.handle[k]]] += xyz(objectForces.force[k]);
  objects->advance(dt);
}

}  // namespace sph
