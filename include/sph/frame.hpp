// A host-side copy of the particles at one instant, ordered by stable particle id: what the
// writers in `io` and embedding applications read.
#pragma once

#include <cstdint>
#include <vector>

namespace sph {

enum class ParticleKind : std::uint8_t { Fluid = 0, Boundary = 1, Object = 2 };

struct ParticleFrame {
  double time = 0.0;
  std::uint64_t step = 0;
  // One entry per particle (n = id.size()); vectors hold x, y, z consecutively (n × 3).
  std::vector<std::uint32_t> id;
  std::vector<float> position;
  std::vector<float> velocity;
  std::vector<float> density;   // kg/m³
  std::vector<float> pressure;  // Pa
  std::vector<std::uint8_t> kind;
  std::vector<std::int32_t> object;  // -1 for fluid and static walls
  // 1 for fluid particles on the free surface (Meteer 2011, eqs. 11-12: |∇c| at the frame's
  // positions, over the last step's neighbours) and object particles on their object's
  // surface.
  std::vector<std::uint8_t> surface;
  // 1 for object particles one of whose springs has broken (a deformable's tear or cut). Empty
  // in frames that carry no tears (made by hand, or read from PLY or CSV): read as 0.
  std::vector<std::uint8_t> torn;

  std::size_t size() const { return id.size(); }
};

// The fluid's arrays where the CPU backend keeps them, read in place: in the engine's own
// order (by grid cell, which changes every step; `id` says whose each row is), not by id.
// Valid until the simulation next steps, loads a state or is destroyed. Empty (count 0, null
// pointers) on the CUDA backend, whose particles live on the GPU: use a ParticleFrame.
struct FluidView {
  std::size_t count = 0;
  std::uint64_t step = 0;  // the step the simulation had taken when it was read
  const std::uint32_t* id = nullptr;
  // Particle k's x, y, z at position[kVectorStride * k + 0..2]; the same for velocity.
  static constexpr std::size_t kVectorStride = 4;
  const float* position = nullptr;  // m
  const float* velocity = nullptr;  // m/s
  const float* density = nullptr;   // kg/m³
  const float* pressure = nullptr;  // Pa
  explicit operator bool() const { return id != nullptr; }
};

}  // namespace sph
