#include "sim/object_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sph/core/contact.hpp"
#include "sph/core/time_step.hpp"
#include "sph/error.hpp"
#include "sph/scene.hpp"

namespace sph::sim {

void ObjectCoupling::receive(FluidEngine& engine, float h) {
  if (!objects) {
    exchange().readIfNew(seenPublication, [&](const ObjectSurface& surface) {
      checkExternalSurface(surface, h);
      objectMaxSpeed = engine.setObjectSurface(surface, params);
      externalSurface = surface;
    });
    return;
  }
  objects->wait();
  objects->exchange().readIfNew(seenPublication, [&](const ObjectSurface& surface) {
    objectMaxSpeed = engine.setObjectSurface(surface, params);
  });
  // Read here, where the engine is known to be idle: the probes sample after the fluid's
  // step, while the engine may be running its own.
  for (std::size_t o = 0; o < contactForceOnObject.size(); ++o)
    contactForceOnObject[o] = objects->world().contactForce(o);
}

void ObjectCoupling::checkExternalSurface(const ObjectSurface& surface, float h) {
  const auto refuse = [&](const std::string& what) {
    throw std::invalid_argument("attached object engine: its publication at t = " +
                                formatNumber(surface.time) + " s " + what);
  };
  externalObjectOfHandle.assign(exchange().handleCount(), -1);
  std::int32_t objectCount = 0;
  for (std::size_t k = 0; k < surface.size(); ++k) {
    const float reach = interaction::contactReach(params, surface.position[k].w);
    if (!(reach <= h))
      refuse("has a particle of radius " + formatNumber(surface.position[k].w) +
             " m whose contact reach, " + formatNumber(reach) +
             " m, passes the fluid's support radius h = " + formatNumber(h) + " m");
    externalObjectOfHandle[surface.handle[k]] = surface.object[k];
    objectCount = std::max(objectCount, surface.object[k] + 1);
  }
  if (fluidForceOnObject.size() < std::size_t(objectCount))
    fluidForceOnObject.resize(std::size_t(objectCount), Vec3{0, 0, 0});
}

void ObjectCoupling::collectForces(FluidEngine& engine, double dt) {
  if (asBoundary() && constraintReactions)
    engine.addConstraintReactions(float(dt));
  else if (asBoundary())
    engine.addBoundaryForces();
  objectForces = engine.downloadObjectForces();
  if (asBoundary()) {  // the pairs within h that pushed
    contactPairs = 0;
    for (const Vec4& f : objectForces.force) contactPairs += std::uint64_t(f.w);
  }
}

void ObjectCoupling::advance(double dt) {
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

double ObjectCoupling::timeStep(const Calibration& calibration, double distanceExponent) const {
  const double travel = travelTimeStep(0.25 * params.fluidRadius, objectMaxSpeed);
  if (params.boundary) return travel;  // no contact springs
  // The stiffest contact is at the centre of the influence sphere, where φ = e^β.
  const double contact = springTimeStep(calibration.mass, calibration.contactStiffness,
                                        distanceFunctionPeak(distanceExponent));
  return std::min(contact, travel);
}

void ObjectCoupling::checkContactReach(const objects::ObjectWorld& world,
                                       const interaction::InteractionParameters& candidate, float h,
                                       const std::string& sourcePath) {
  float largest = 0.0f;
  for (float r : world.particles().radius)
    largest = std::max(largest, interaction::contactReach(candidate, r));
  if (largest > h) {
    std::ostringstream message;
    message << sourcePath << ": interaction.influence_ratio: the influence sphere reaches "
            << largest << " m, past the fluid's support radius h = " << h
            << " m; expected a smaller ratio or object spacing";
    throw InputError(message.str());
  }
}

}  // namespace sph::sim
