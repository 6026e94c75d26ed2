// What a user changes while the simulation runs (the viewer): parameters, and kinematic objects
// dragged by hand.
#include <cmath>
#include <sstream>
#include <string>

#include "sim/simulation_impl.hpp"
#include "sph/core/eos.hpp"

namespace sph {

namespace {

void require(bool ok, const std::string& where, const char* key, const char* expected, double got) {
  if (ok) return;
  std::ostringstream message;
  message << where << ": " << key << ": expected " << expected << ", got " << got;
  throw InputError(message.str());
}

}  // namespace

LiveParameters Simulation::liveParameters() const {
  const Impl& s = *impl_;
  LiveParameters out;
  out.viscosity = s.scene.fluid.viscosity;
  out.stiffness = s.calibration.stiffness;
  out.gravity = s.scene.gravity;
  out.surfaceTension = s.scene.fluid.surfaceTension;
  out.influenceRatio = s.scene.interaction.influenceRatio;
  return out;
}

void Simulation::setLiveParameters(const LiveParameters& values) {
  Impl& s = *impl_;
  const std::string& where = s.scene.sourcePath;
  require(values.viscosity >= 0.0 && std::isfinite(values.viscosity), where, "fluid.viscosity",
          "a number ≥ 0", values.viscosity);
  require(values.stiffness > 0.0 && std::isfinite(values.stiffness), where, "calibration.stiffness",
          "a positive number", values.stiffness);
  require(values.surfaceTension >= 0.0 && std::isfinite(values.surfaceTension), where,
          "fluid.surface_tension", "a number ≥ 0", values.surfaceTension);
  for (double g : values.gravity) require(std::isfinite(g), where, "gravity", "finite numbers", g);
  require(values.influenceRatio > 0.0 && std::isfinite(values.influenceRatio), where,
          "interaction.influence_ratio", "a positive number", values.influenceRatio);

  Scene next = s.scene;
  next.fluid.viscosity = values.viscosity;
  next.fluid.surfaceTension = values.surfaceTension;
  next.gravity = values.gravity;
  next.interaction.influenceRatio = values.influenceRatio;
  next.calibration.stiffness = values.stiffness;
  next.calibration.speedOfSound =
      soundSpeedForStiffness(next.fluid.eos, values.stiffness, next.fluid.restDensity);

  Calibration calibration = sim::calibrate(next, s.coupling.externalExchange != nullptr);
  calibration.fluidParticles = s.calibration.fluidParticles;
  calibration.boundaryParticles = s.calibration.boundaryParticles;
  calibration.objectParticles = s.calibration.objectParticles;
  const interaction::InteractionParameters interaction =
      s.coupling.coupled() ? sim::interactionParameters(next, calibration) : s.coupling.params;
  if (s.coupling.objects) {
    s.coupling.objects->wait();
    sim::ObjectCoupling::checkContactReach(s.coupling.objects->world(), interaction, s.params.h,
                                           s.scene.sourcePath);
  }
  s.scene = std::move(next);
  s.calibration = calibration;
  s.params = sim::fluidParameters(s.scene, s.calibration);
  s.coupling.params = interaction;
  s.engine->setParameters(s.params);
}

void Simulation::steerObject(const std::string& name, const Vec3d& offset, double arriveIn) {
  Impl& s = *impl_;
  for (std::size_t o = 0; o < s.scene.objects.size(); ++o) {
    if (s.scene.objects[o].name != name || s.scene.objects[o].motion != ObjectMotion::Kinematic)
      continue;
    s.coupling.objects->wait();
    s.coupling.objects->world().steer(o, Vec3{float(offset[0]), float(offset[1]), float(offset[2])},
                                      arriveIn);
    return;
  }
  throw InputError(s.scene.sourcePath + ": steerObject: no kinematic object is named '" + name +
                   "'");
}

}  // namespace sph
