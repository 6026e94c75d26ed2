// What a substep of the position solver is asked for (pbf_solve.hpp, core/pbf.hpp).
#pragma once

namespace sph::fluid {

struct PbfSettings {
  int iterations = 3;
  float relaxation = 0.0f;       // ε, 1/m²
  float tensileStrength = 0.0f;  // k of s_corr, over the full lattice's gradient sum
  float tensileDistance = 0.0f;  // Δq, m
};

}  // namespace sph::fluid
