// The fluid's side of the coupling with objects (Meteer 2011, §7): the engine's surface
// particles in, the forces on them out, the engine's step handed over, and the step the
// objects allow. The engine is the built-in one (an ObjectRunner) or one the user attached,
// known only through its exchange; with neither the scene has no objects.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sim/fluid_engine.hpp"
#include "sim/object_runner.hpp"
#include "sph/calibration.hpp"
#include "sph/object_exchange.hpp"

namespace sph::sim {

struct ObjectCoupling {
  std::unique_ptr<ObjectRunner> objects;
  std::shared_ptr<ObjectExchange> externalExchange;
  std::vector<std::int32_t> externalContainers;  // by fluid id: the attached object holding it
  ObjectSurface externalSurface;  // the attached engine's newest publication read, for frames
  std::vector<std::int32_t> externalObjectOfHandle;  // from the newest publication read
  interaction::InteractionParameters params{};
  std::uint64_t seenPublication = 0;
  float objectMaxSpeed = 0.0f;
  std::uint64_t contactPairs = 0;
  HostObjectForces objectForces;
  std::vector<Vec3> fluidForceOnObject;    // by object, last step
  std::vector<Vec3> contactForceOnObject;  // by object, over the engine's last finished step

  // Under the position solver the reactions are of its density constraints' push, not of a
  // pressure (interaction/boundary_forces.hpp).
  bool constraintReactions = false;

  bool coupled() const { return objects || externalExchange; }
  ObjectExchange& exchange() { return objects ? objects->exchange() : *externalExchange; }
  // Akinci et al. 2012's boundary particles in the fluid's pressure, rather than contacts.
  bool asBoundary() const { return coupled() && params.boundary; }

  // Meteer 2011, §7, step 2: the engine's newest surface particles into the fluid's engine,
  // waiting for the built-in engine's step to finish. h: the fluid's support radius, which an
  // attached engine's contact reach may not pass.
  void receive(FluidEngine& engine, float h);
  // An attached engine's publication (whose handles and object ids publish() checked): radii
  // whose contact reach the fluid's grid can search. Remembers each handle's object.
  void checkExternalSurface(const ObjectSurface& surface, float h);
  // Meteer 2011, §7, steps 3-4: collisions and contact forces (with boundary coupling, only
  // whether each fluid particle is still inside its container).
  void computeContacts(FluidEngine& engine) { contactPairs = engine.computeContacts(params); }
  // The fluid's forces on the objects' particles: the contact forces, or with boundary
  // coupling the reactions of the pressure the solves have just given, or of the push the
  // position solver's constraints gave over the step dt.
  void collectForces(FluidEngine& engine, double dt);
  // The engine receives this step's forces and takes its own step(s) over dt.
  void advance(double dt);

  // Meteer 2011, §8.3: contacts stay resolved, and no object particle moves more than a quarter
  // of the fluid's radius in a step, so nothing tunnels.
  double timeStep(const Calibration& calibration, double distanceExponent) const;

  // Contacts are found through the fluid's grid (cell edge h) from the object particles:
  // refuses, naming the scene's key, an influence sphere that reaches past h.
  static void checkContactReach(const objects::ObjectWorld& world,
                                const interaction::InteractionParameters& candidate, float h,
                                const std::string& sourcePath);
};

}  // namespace sph::sim
