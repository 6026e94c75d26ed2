// The CUDA–OpenGL path: a CUDA simulation's fluid written into the renderer's GL buffers holds
// the frame's positions. Needs a GPU and an OpenGL context on it; skipped, with the reason,
// without them.
#include "cuda_gl_fluid.hpp"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "offscreen_context.hpp"
#include "particle_colours.hpp"
#include "scene/scene_loader.hpp"
#include "sph/devices.hpp"

namespace sph::view {
namespace {

using Point = std::array<float, 3>;

TEST(CudaGlFluid, WritesTheFluidIntoTheRenderersBuffers) {
  if (!cudaGlInteropBuilt()) GTEST_SKIP() << "this build has no CUDA backend";
  const GpuReport gpus = queryGpus();
  if (gpus.devices.empty()) GTEST_SKIP() << "no GPU: " << gpus.reason;
  std::unique_ptr<render::OffscreenContext> context;
  try {
    context = std::make_unique<render::OffscreenContext>(64, 64);
  } catch (const render::ContextUnavailable& e) {
    GTEST_SKIP() << "no offscreen OpenGL context: " << e.what();
  }
  SimulationOptions options;
  options.backend = Backend::Cuda;
  const Scene scene = scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/artery_squeeze.json");
  Simulation sim(scene, options);
  for (int i = 0; i < 10; ++i) sim.step();

  auto renderer = std::make_unique<render::ParticleRenderer>();
  renderer->reserve(sim.fluidCount() + 10);
  std::unique_ptr<CudaGlFluid> interop;
  try {
    interop = std::make_unique<CudaGlFluid>(*renderer);
  } catch (const std::runtime_error& e) {
    renderer.reset();
    GTEST_SKIP() << "the OpenGL context is not on the GPU: " << e.what();
  }
  const render::FluidColourTable table =
      render::fluidColourTable(render::ColourMode::Density, {990.0f, 1010.0f}, true);
  const std::size_t n = interop->write(sim, FluidQuantity::Density, table);
  ASSERT_EQ(n, sim.fluidCount());

  std::vector<float> drawn(4 * n);
  glBindBuffer(GL_ARRAY_BUFFER, renderer->positionBuffer().name);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(drawn.size() * sizeof(float)), drawn.data());
  std::vector<std::uint8_t> colours(4 * n);
  glBindBuffer(GL_ARRAY_BUFFER, renderer->colourBuffer().name);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(colours.size()), colours.data());

  const ParticleFrame frame = sim.frame(false);
  std::vector<Point> expected, got;
  for (std::size_t k = 0; k < frame.size(); ++k)
    if (frame.kind[k] == std::uint8_t(ParticleKind::Fluid))
      expected.push_back(
          {frame.position[3 * k], frame.position[3 * k + 1], frame.position[3 * k + 2]});
  for (std::size_t i = 0; i < n; ++i)
    got.push_back({drawn[4 * i], drawn[4 * i + 1], drawn[4 * i + 2]});
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, expected);
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(colours[4 * i + 3], 255) << "particle " << i;

  interop.reset();  // unregistered while the context is current
  renderer.reset();
}

}  // namespace
}  // namespace sph::view
