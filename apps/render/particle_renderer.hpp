// Draws a frame's particles as shaded spheres, coloured through colour_map / particle_colours,
// or its fluid as a liquid surface, with an optional domain box, grid and colour bar. It needs only
// a current OpenGL 3.3 core context (an OffscreenContext, or a window's) and draws into whatever
// framebuffer is bound.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "camera.hpp"
#include "colour_map.hpp"
#include "liquid_style.hpp"
#include "particle_colours.hpp"
#include "sph/frame.hpp"
#include "sph/object_surface.hpp"

namespace sph::render {

class LiquidSurface;

struct DrawSettings {
  ColourMode colour = ColourMode::Kind;
  std::optional<ValueRange> range;  // none: taken from the particles (rangeFromFrames)
  ParticleFilter show;              // fluid, walls, objects
  float particleRadius = 0.005f;    // world units: half the particle spacing
  bool showDomain = false;          // the domain's edges
  bool showGrid = false;            // the uniform grid's cells on the domain's far faces
  Box3f domain;
  float gridCellSize = 0.0f;  // the support radius h
  bool showColourBar = true;  // for the modes that map a quantity
  // Leave out the walls and objects between the camera and its target (the plane through the
  // target facing the camera), so the fluid inside a vessel shows.
  bool cutaway = false;
  Rgb background{0.11f, 0.12f, 0.14f};
  // The fluid as spheres coloured by `colour`, or as a liquid surface (liquid_surface.hpp),
  // the walls and objects as spheres either way.
  Look look = Look::Particles;
  LiquidStyle liquid;
  // Objects with a surface (setObjectSurfaces) drawn as it, deforming and torn with them; the
  // others, and all when false, as spheres.
  bool objectSurfaces = true;
};

class ParticleRenderer {
 public:
  // Compiles the shaders; throws std::runtime_error when they do not compile.
  ParticleRenderer();
  // Needs the same context current.
  ~ParticleRenderer();
  ParticleRenderer(const ParticleRenderer&) = delete;
  ParticleRenderer& operator=(const ParticleRenderer&) = delete;

  // Uploads positions now; colours follow at the next draw, for its settings.
  void setParticles(const ParticleFrame& frame);
  // The surfaces objects are drawn with, anchored on the frames' particle ids (a run's
  // object_surfaces.vtp, or Simulation::objectSurfaces()); empty: objects as particles.
  void setObjectSurfaces(std::vector<ObjectSurfaceMesh> surfaces);
  // Room for `particles` in the position and colour buffers. Growing replaces their storage,
  // so a CUDA registration of them must be made again.
  void reserve(std::size_t particles);
  // For a fluid written on the GPU (CUDA–OpenGL interop): the first `fluidCount` entries of
  // positionBuffer() and colourBuffer() already hold the fluid, coloured through a
  // FluidColourTable over `fluidRange`; `solids` (walls and objects, no fluid) are uploaded
  // from the host behind them, and coloured at the next draw.
  void setParticlesBehindFluid(std::size_t fluidCount, ValueRange fluidRange,
                               const ParticleFrame& solids);
  // Clears and draws into the bound framebuffer's (0, 0, width, height).
  void draw(const OrbitCamera& camera, const DrawSettings& settings, int width, int height);

  std::size_t particleCount() const { return fluidOnGpu_ + frame_.size(); }
  // The range the last draw mapped colours over (its settings' or the particles').
  ValueRange rangeUsed() const { return range_; }
  // The liquid view's passes, once a draw has used them (for tests); else null.
  const LiquidSurface* liquidSurface() const { return liquid_.get(); }

  // The GL buffer of positions, 4 floats per particle (x, y, z, unused), with room for
  // `capacity` particles: a GPU simulation can write into it through CUDA–OpenGL interop
  // instead of copying through the host.
  struct GlBuffer {
    unsigned name = 0;
    std::size_t capacity = 0;
  };
  GlBuffer positionBuffer() const { return {positionBuffer_, capacity_}; }
  // RGBA8 per particle, alpha 0 for one not shown.
  GlBuffer colourBuffer() const { return {colourBuffer_, capacity_}; }

 private:
  struct Programs;
  void uploadPositions(const ParticleFrame& frame, std::size_t offset);
  void uploadColours(const DrawSettings& settings, const OrbitCamera& camera);
  void drawParticles(const Mat4f& view, const Mat4f& projection, const DrawSettings& settings,
                     int height);
  void drawLines(const std::vector<float>& lines, const Mat4f& viewProjection, const Rgb& colour);
  void drawColourBar(int width, int height);

  void drawLiquid(const Mat4f& view, const Mat4f& projection, const DrawSettings& settings,
                  int width, int height);
  void drawObjectSurfaces(const Mat4f& view, const Mat4f& projection,
                          const std::optional<CutPlane>& cut);
  void uploadLiquid();

  std::unique_ptr<Programs> programs_;
  std::unique_ptr<LiquidSurface> liquid_;
  unsigned liquidVao_ = 0, liquidBuffer_ = 0;  // the host frame's fluid alone
  std::size_t liquidCount_ = 0;
  bool liquidStale_ = false;  // frame_ changed since the liquid's buffer was filled
  std::vector<ObjectSurfaceMesh> surfaces_;
  std::vector<std::uint8_t> objectHasSurface_;  // by object index
  unsigned surfaceVao_ = 0, surfaceBuffer_ = 0;
  unsigned particleVao_ = 0, positionBuffer_ = 0, colourBuffer_ = 0;
  unsigned lineVao_ = 0, lineBuffer_ = 0;
  unsigned overlayVao_ = 0, overlayBuffer_ = 0;
  std::size_t capacity_ = 0;
  std::size_t fluidOnGpu_ = 0;  // entries ahead of frame_'s, written on the GPU
  ValueRange fluidOnGpuRange_;
  ParticleFrame frame_;
  ValueRange range_;
};

// The bound read framebuffer's pixels as RGB bytes, top row first (as images are stored).
std::vector<std::uint8_t> readRgbPixels(int width, int height);

}  // namespace sph::render
