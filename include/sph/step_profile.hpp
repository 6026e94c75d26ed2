// What a step cost, stage by stage, and what the incompressible solver did in it.
#pragma once

namespace sph {

// Wall-clock milliseconds of each stage of the last step (the step's profile).
struct StepProfile {
  double buildGrid = 0.0;
  double densityPressure = 0.0;
  double divergenceSolve = 0.0;  // DFSPH
  double forces = 0.0;
  double interaction = 0.0;  // collisions and contact forces with objects (Meteer 2011, §7)
  double timeStep = 0.0;
  double densitySolve = 0.0;  // DFSPH
  double integrate = 0.0;
  double objects = 0.0;     // handing the step to the object engine (its own thread by default)
  double wallForces = 0.0;  // the fluid's force on the walls a force probe reads
  double flow = 0.0;        // emitters: the inflow driven, the new particles put in
  double probes = 0.0;      // sampling the scene's probes
  double exchange = 0.0;    // a distributed run: particles and densities between processes
  double total() const {
    return buildGrid + densityPressure + divergenceSolve + forces + interaction + timeStep +
           densitySolve + integrate + objects + wallForces + flow + probes + exchange;
  }
};

// The incompressible solver's (DFSPH) last step; all zero for the weakly compressible solver.
struct SolverStats {
  int densityIterations = 0;     // velocity corrections of the density solve, warm start aside
  int divergenceIterations = 0;  // the same for the divergence solve
  double densityError = 0.0;     // average ρ/ρ0 - 1 the step ends with, as the solve predicted
  double largestDensityError = 0.0;  // of one particle
  double divergenceError = 0.0;      // average Δt (Dρ/Dt) / ρ0 left by the divergence solve
  bool converged = true;             // both met their tolerance within their iterations
};

}  // namespace sph
