// A closed deformable filled with liquid keeps the volume it encloses: an incompressible fluid
// inside cannot tell the vessel so through its pressure. Its solve holds the vessel still while
// it runs, so that a clamp closing on the vessel meets fluid that has nowhere to go, is pushed
// back as hard as the solve's iterations allow, and overshoots the next step (the
// "incompressibility dilemma" of Küttler, Förster & Wall, 2006, who give the structure the
// enclosed fluid's volume constraint, as here). It is one more XPBD constraint on the vessel's
// outer particles:
//   C = V(x) − V0,   ∇_k C = A n_k,
// with V the volume the particles' surface encloses, V0 the shape's, n_k the outward normal at
// particle k and A_k the area it stands for: its share at rest, times the mean squared stretch
// of its distances to its outer neighbours. Within an engine step the normals and areas stay as
// the step began, so V is linear in the positions: V(x) = V_start + Σ_k A_k n_k · (x_k −
// x_k,start). A torn vessel is open: its constraint lapses for good.
#pragma once

#include <cstdint>
#include <vector>

#include "objects/math3d.hpp"
#include "sph/core/vec.hpp"

namespace sph::objects {

struct VolumeConstraint {
  std::size_t object = 0;              // index of the deformable
  std::size_t network = 0;             // its spring network
  std::vector<std::uint32_t> surface;  // its outer particles
  // Outer particle m's outer rest neighbours: neighbour[neighbourStart[m] .. [m + 1]), as
  // particle indices, with their squared distances at rest.
  std::vector<std::uint32_t> neighbourStart, neighbour;
  std::vector<double> restDistance2;
  double restArea = 0.0;             // m² per outer particle at rest
  double restVolume = 0.0;           // V0, m³
  double startVolume = 0.0;          // V at the engine step's start
  std::vector<DVec3> startPosition;  // per outer particle, at the step's start
  std::vector<DVec3> gradient;       // A_k n_k per outer particle, at the step's start
  double weight = 0.0;               // Σ w_k |∇_k C|², at the step's start
};

// The constraint of a closed shape of volume `volume` whose outer particles (`surface`) sit at
// `position` with `normal`, at rest; `neighbourStart`/`neighbours` are the rest neighbours of
// particles first.. (SpringNetwork's). The rest area per particle makes the particles' volume
// equal the shape's.
VolumeConstraint makeVolumeConstraint(std::size_t object, std::size_t network,
                                      std::vector<std::uint32_t> surface, double volume,
                                      const std::vector<DVec3>& position,
                                      const std::vector<Vec3>& normal, std::size_t first,
                                      const std::vector<std::uint32_t>& neighbourStart,
                                      const std::vector<std::uint32_t>& neighbours);

// The volume the outer particles enclose: (1/3) Σ_k (x_k − c) · n_k A_k, c their centroid (the
// divergence theorem, each particle a patch of its surface).
double enclosedVolume(const VolumeConstraint& c, const std::vector<DVec3>& position,
                      const std::vector<Vec3>& normal);

// At an engine step's start: the volume now, the positions and gradients it is linear about,
// and the projection's weight. `inverseMass` per particle index, 0 where pinned.
void beginVolumeStep(VolumeConstraint& c, const std::vector<DVec3>& position,
                     const std::vector<Vec3>& normal, const std::vector<double>& inverseMass);

// The volume the linearised constraint reads at `position`, m³.
double linearisedVolume(const VolumeConstraint& c, const std::vector<DVec3>& position);

// One XPBD projection with the multiplier from 0 and no compliance (the fluid is
// incompressible): Δλ = −C / Σ w_k |∇_k C|², Δx_k = w_k ∇_k C Δλ, with the weight of the
// step's start (beginVolumeStep).
void projectVolume(const VolumeConstraint& c, const std::vector<double>& inverseMass,
                   std::vector<DVec3>& position);

}  // namespace sph::objects
