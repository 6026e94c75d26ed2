// What a substep of the position solver is asked for (pbf_solve.hpp, core/pbf.hpp).
#pragma once

namespace sph::fluid {

struct PbfSettings {
  int iterations = 3;
  float relaxation = 0.0f;       // ε, 1/m²
  float tensileStrength = 0.0f;  // k of s_corr, over the full lattice's gradient sum
  float tensileDistance = 0.0f;  // Δq, m
  // The last guard: a speed past it is limited to it and counted (SolverReport::clamped).
  float maxSpeed = 3.0e38f;  // m/s
};

}  // namespace sph::fluid
