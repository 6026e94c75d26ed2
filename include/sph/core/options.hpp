// The method choices a scene makes; stages branch on them once per pass, never per pair.
#pragma once

namespace sph {

enum class KernelKind { Muller, CubicSpline, WendlandC2 };
enum class EquationOfState { Linear, Ratio, Tait };  // k(ρ-ρ0), k(ρ/ρ0-1), B((ρ/ρ0)^7-1)
enum class PressureForm { Paper, Symmetric };        // (p_i+p_j)/(2ρ_j) or p_i/ρ_i²+p_j/ρ_j²
enum class ViscosityModel { Muller, Artificial };
// Weakly compressible (an equation of state gives pressure), incompressible (DFSPH solves for
// it), or position based (PBF: a density constraint on the positions, solved in substeps).
enum class FluidSolver { Wcsph, Dfsph, Pbf };

// The weakly compressible solver's density: summed from the neighbours each step (Meteer 2011,
// eq. 4), or integrated by the continuity equation with δ-SPH's density diffusion.
enum class DensityModel { Summation, Continuity };

}  // namespace sph
