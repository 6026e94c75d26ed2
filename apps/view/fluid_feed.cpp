#include "fluid_feed.hpp"

#include <cstring>
#include <stdexcept>

#include "particle_colours.hpp"

namespace sph::view {

namespace {

constexpr std::chrono::seconds kRangeRefresh{1};

}  // namespace

FluidFeed::FluidFeed(render::ParticleRenderer& renderer, const Simulation& sim)
    : renderer_(renderer), path_("fluid through host copies") {
  const Calibration& c = sim.calibration();
  reserved_ = c.fluidParticles + c.boundaryParticles + c.objectParticles;
  renderer_.reserve(reserved_);
  if (std::strcmp(sim.backendName(), "cuda") != 0) return;
  try {
    interop_ = std::make_unique<CudaGlFluid>(renderer_);
    path_ = "fluid drawn from the GPU (CUDA-OpenGL interop)";
  } catch (const std::runtime_error& e) {
    path_ = std::string("fluid through host copies: ") + e.what();
  }
}

render::ValueRange FluidFeed::fluidRange(const Simulation& sim, const render::DrawSettings& draw) {
  if (draw.range) return *draw.range;
  const auto now = std::chrono::steady_clock::now();
  if (!range_ || rangeMode_ != draw.colour || now - rangeTaken_ >= kRangeRefresh) {
    const ParticleFrame fluid = sim.frame(false);
    range_ = render::rangeFromFrames({&fluid}, draw.colour);
    rangeMode_ = draw.colour;
    rangeTaken_ = now;
  }
  return *range_;
}

void FluidFeed::feed(const Simulation& sim, const render::DrawSettings& draw) {
  const Calibration& c = sim.calibration();
  if (interop_ && sim.fluidCount() + c.boundaryParticles + c.objectParticles > reserved_) {
    // Emitters have put in more than the buffers interop registered hold: growing them
    // would leave the registration behind.
    interop_.reset();
    path_ = "fluid through host copies: the emitters outgrew the buffers drawn from the GPU";
  }
  if (!interop_) {
    renderer_.setParticles(sim.frame(draw.show.boundary));
    return;
  }
  const render::ValueRange range =
      render::usesRange(draw.colour) ? fluidRange(sim, draw) : render::ValueRange{};
  const std::size_t fluid =
      interop_->write(sim, render::quantityShown(draw.colour),
                      render::fluidColourTable(draw.colour, range, draw.show.fluid));
  renderer_.setParticlesBehindFluid(fluid, range, sim.solidFrame(draw.show.boundary));
}

}  // namespace sph::view
