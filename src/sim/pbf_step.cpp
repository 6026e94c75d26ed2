// The position-based substep: Position Based Fluids (Macklin & Müller 2013). The velocities
// take the last substep's non-pressure forces and predict the positions; the neighbours are
// found once at the predicted positions; a few Jacobi iterations project the density
// constraints onto the positions; the velocity is what the move implies, smoothed by XSPH.
// The forces (gravity, viscosity, surface tension, external accelerations) are found last, at
// the corrected positions, for the next substep. A substep is time.frame_dt / substeps long.
// Objects are boundary particles of the density constraints, where the last substep's object
// step left them: the constraints push the fluid off them as off the walls, and the object
// step takes the opposite of that push (interaction/boundary_forces.hpp) over the substep.
#include "sim/simulation_impl.hpp"

namespace sph {

std::vector<Simulation::Impl::Stage> Simulation::Impl::pbfStages() const {
  std::vector<Stage> list;
  list.push_back({"time step", &StepProfile::timeStep, &Impl::chooseTimeStep});
  list.push_back({"predict positions", &StepProfile::integrate, &Impl::predictPositions});
  // Read after the prediction, which runs while the object step finishes.
  if (coupling.asBoundary())
    list.push_back({"objects as boundary", &StepProfile::interaction, &Impl::receiveObjects});
  list.push_back({"build grid", &StepProfile::buildGrid, &Impl::buildGrid});
  list.push_back({"density", &StepProfile::densityPressure, &Impl::sumDensity});
  list.push_back({"density constraints", &StepProfile::densitySolve, &Impl::solvePositions});
  if (scene.fluid.pbf.xsph > 0.0)
    list.push_back({"XSPH viscosity", &StepProfile::forces, &Impl::smoothVelocities});
  list.push_back({"non-pressure forces", &StepProfile::forces, &Impl::computeForces});
  if (coupling.asBoundary()) {
    list.push_back({"containment", &StepProfile::interaction, &Impl::checkContainment});
    list.push_back({"forces on objects", &StepProfile::interaction, &Impl::collectObjectForces});
  }
  // The solve has moved the particles already.
  addStepEnd(list, {"advance clock", &StepProfile::integrate, &Impl::advanceClock});
  return list;
}

void Simulation::Impl::solvePositions() {
  const PbfDesc& d = scene.fluid.pbf;
  fluid::PbfSettings s;
  s.iterations = d.iterations;
  s.relaxation = float(d.relaxation * calibration.pbfGradientSquares);
  s.tensileStrength = float(d.tensileStrength / calibration.pbfGradientSquares);
  s.tensileDistance = float(d.tensileDistance * calibration.supportRadius);
  s.maxSpeed = float(calibration.pbfSpeedGuard);
  const fluid::SolverReport report = engine->solvePositions(s, float(clock.dt));
  counts.clamped += report.clamped;
  solves.addDensity(report);
}

}  // namespace sph
