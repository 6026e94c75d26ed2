// How many particles a scene will make, and the memory they take, known before any of them is
// sampled: a scene the machine cannot hold is refused with its count instead of ending in an
// allocation failure minutes later.
#pragma once

#include <cstdint>

#include "sph/scene.hpp"

namespace sph::sim {

struct SceneSize {
  double fluidParticles = 0.0;   // at most: the blocks' lattices before walls and objects clip them
  double wallParticles = 0.0;    // at most, meshes left out (their size is known once read)
  double objectParticles = 0.0;  // at most, meshes left out
  double bytes = 0.0;            // the engine's arrays for both
};

SceneSize estimateSize(const Scene& scene);

// The memory the process may count on: the machine's physical memory.
double availableBytes();

// Throws InputError naming the scene file, the key, the particle count and the memory when the
// scene needs more than `machineBytes`, or more than its `limits` allow.
void refuseIfTooLarge(const Scene& scene, double machineBytes);

}  // namespace sph::sim
