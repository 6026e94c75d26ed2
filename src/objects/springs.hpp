// A deformable object's spring network (Meteer 2011, §4.3, §8.2): springs between particles
// that are close at rest, with damping along each spring, breaking past a strain; and the
// normals that follow the deformed surface.
#pragma once

#include <cstdint>
#include <vector>

#include "objects/math3d.hpp"
#include "sph/scene.hpp"

namespace sph::objects {

struct Spring {
  std::uint32_t a, b;  // particle indices, a < b
  double restLength;   // m
};

// Two neighbours a, b spanning a particle's tangent plane at rest give it a local frame
// t1 = (x_a − x)/|·|, t3 = t1 × (x_b − x)/|·|, t2 = t3 × t1, in which the rest normal is stored
// (n = c1 t1 + c2 t2 + c3 t3): it tells which side of the surface is out as it deforms.
struct NormalFrame {
  std::uint32_t a = 0, b = 0;
  DVec3 coefficients;  // (c1, c2, c3)
  bool valid = false;  // false: no usable pair
};

struct SpringNetwork {
  std::vector<Spring> springs;       // sorted by (a, b)
  std::vector<std::uint8_t> broken;  // per spring, permanent
  std::size_t brokenCount = 0;
  double stiffness = 0.0;       // N/m
  double damping = 0.0;         // N·s/m along the spring
  double breakingStrain = 0.0;  // 0: never
  // The rest neighbours of particle first + k: neighbours[neighbourStart[k] ..
  // neighbourStart[k + 1]), as particle indices; they give the surface's local plane.
  std::vector<std::uint32_t> neighbourStart;
  std::vector<std::uint32_t> neighbours;
  std::vector<NormalFrame> frames;  // per particle of the object
  std::size_t first = 0, count = 0;
};

// Springs between every two of the particles [first, first + count) closer than `reach` at
// rest, all intact.
SpringNetwork buildSprings(const std::vector<DVec3>& position, const std::vector<DVec3>& normal,
                           std::size_t first, std::size_t count, double reach);

// Hooke's law plus a dashpot on the relative velocity along the spring:
// f_a = [k (l − l0) + c (v_b − v_a)·u] u, u = (x_b − x_a)/l, and f_b = −f_a.
void addSpringForces(const SpringNetwork& net, const std::vector<DVec3>& position,
                     const std::vector<DVec3>& velocity, std::vector<DVec3>& force);

// Breaks every spring strained past breakingStrain and marks both of its particles cut.
void breakOverstretched(SpringNetwork& net, const std::vector<DVec3>& position,
                        std::vector<std::uint8_t>& cut);

// The normal of each particle of the network: its rest normal carried by its frame, or, where
// that points more than 60° away from its neighbours' (a crease), their mean. Pinned particles
// keep `restNormal`.
void updateNormals(const SpringNetwork& net, const std::vector<DVec3>& position,
                   const std::vector<DVec3>& restNormal, const std::vector<std::uint8_t>& pinned,
                   std::vector<Vec3>& normal);

}  // namespace sph::objects
