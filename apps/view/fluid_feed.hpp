// Hands the simulation's particles to the renderer each display frame. On the CUDA backend the
// fluid goes from the GPU straight into the renderer's buffers (CudaGlFluid), and only the
// walls and objects cross the host; otherwise, or when interop cannot start, the whole frame
// is copied through the host.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "cuda_gl_fluid.hpp"
#include "particle_renderer.hpp"
#include "sph/simulation.hpp"

namespace sph::view {

class FluidFeed {
 public:
  // Reserves the renderer's room for every particle of `sim` and starts interop when `sim`
  // runs on the GPU. Needs the renderer's context current.
  FluidFeed(render::ParticleRenderer& renderer, const Simulation& sim);
  // Hands over the particles of `sim` (the same scene, perhaps reset) for `draw`.
  void feed(const Simulation& sim, const render::DrawSettings& draw);

  bool fluidFromGpu() const { return interop_ != nullptr; }
  // How the fluid reaches the renderer, for the panel.
  const std::string& path() const { return path_; }

 private:
  render::ValueRange fluidRange(const Simulation& sim, const render::DrawSettings& draw);

  render::ParticleRenderer& renderer_;
  std::unique_ptr<CudaGlFluid> interop_;
  std::size_t reserved_ = 0;  // the particles interop's buffers hold
  std::string path_;
  // The colour range of a fluid drawn from the GPU, when the settings give none: taken from a
  // host copy once a second, which is all that crosses the host for the fluid.
  std::optional<render::ValueRange> range_;
  render::ColourMode rangeMode_ = render::ColourMode::Kind;
  std::chrono::steady_clock::time_point rangeTaken_;
};

}  // namespace sph::view
