// Where and how a Simulation runs: its backend, device and threads.
#pragma once

#include <cstdint>

namespace sph {

enum class Backend { Cpu, Cuda, Auto };  // Auto: the GPU when one is present

// How the CPU backend's passes take neighbours: a SIMD batch at a time (the default), or one
// at a time through the neighbour lists as the GPU does, the reference the first is tested and
// timed against. The CUDA backend ignores it.
enum class CpuPasses { Batched, OneAtATime };

struct SimulationOptions {
  Backend backend = Backend::Cpu;
  int device = 0;  // CUDA device index
  CpuPasses cpuPasses = CpuPasses::Batched;
  // The most fluid neighbours listed per particle; a particle with more finds them in the
  // grid's cells instead, slower and with the same physics. 0: room for twice the neighbours
  // of the initial lattice.
  std::uint32_t neighborListLength = 0;
  // CPU threads for the simulation's passes, at most 1024; 0: the calling thread's OpenMP
  // setting (every hardware thread unless the program set it). Results do not depend on it.
  int threads = 0;
};

}  // namespace sph
