#include "particle_renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "colour_bar.hpp"
#include "gl_program.hpp"
#include "liquid_surface.hpp"
#include "object_surfaces.hpp"
#include "shaders.hpp"
#include "wireframe.hpp"

namespace sph::render {

struct ParticleRenderer::Programs {
  GlProgram spheres{"sphere", shaders::kSphereVertex, shaders::kSphereFragment};
  GlProgram lines{"line", shaders::kLineVertex, shaders::kLineFragment};
  GlProgram overlay{"overlay", shaders::kOverlayVertex, shaders::kOverlayFragment};
  GlProgram surfaces{"object surface", shaders::kSurfaceVertex, shaders::kSurfaceFragment};
};

namespace {

// Light from the upper left, slightly in front: a 3/4 view's spheres read as round.
constexpr float kLight[3] = {-0.40f, 0.70f, 0.59f};

// The liquid's spheres in units of the particles' (half a spacing): a little larger, so that
// neighbours overlap and the smoothing has one surface to flatten rather than a lattice of
// bumps with holes between, and not so large that the liquid swells past the particles' edge
// (at twice the size it covered 9 % more of a block's picture than its particles).
constexpr float kLiquidRadius = 1.25f;

void vertexAttribute(GLuint index, GLint components, GLenum type, GLboolean normalised,
                     GLsizei stride, std::size_t offset) {
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, components, type, normalised, stride,
                        reinterpret_cast<const void*>(offset));
}

// Lines a little lighter than the background, so they show without competing with the fluid.
Rgb lineColour(const Rgb& background, float lift) {
  return {background.r + lift, background.g + lift, background.b + lift};
}

std::optional<CutPlane> cutPlane(const DrawSettings& settings, const OrbitCamera& camera) {
  if (!settings.cutaway) return std::nullopt;
  return CutPlane{camera.target, normalize(subtract(camera.target, camera.eye()))};
}

}  // namespace

ParticleRenderer::ParticleRenderer() : programs_(std::make_unique<Programs>()) {
  glGenVertexArrays(1, &particleVao_);
  glGenBuffers(1, &positionBuffer_);
  glGenBuffers(1, &colourBuffer_);
  glBindVertexArray(particleVao_);
  glBindBuffer(GL_ARRAY_BUFFER, positionBuffer_);
  vertexAttribute(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), 0);
  glBindBuffer(GL_ARRAY_BUFFER, colourBuffer_);
  vertexAttribute(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, 4, 0);

  glGenVertexArrays(1, &lineVao_);
  glGenBuffers(1, &lineBuffer_);
  glBindVertexArray(lineVao_);
  glBindBuffer(GL_ARRAY_BUFFER, lineBuffer_);
  vertexAttribute(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), 0);

  glGenVertexArrays(1, &liquidVao_);
  glGenBuffers(1, &liquidBuffer_);
  glBindVertexArray(liquidVao_);
  glBindBuffer(GL_ARRAY_BUFFER, liquidBuffer_);
  vertexAttribute(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), 0);

  glGenVertexArrays(1, &surfaceVao_);
  glGenBuffers(1, &surfaceBuffer_);
  glBindVertexArray(surfaceVao_);
  glBindBuffer(GL_ARRAY_BUFFER, surfaceBuffer_);
  constexpr GLsizei corner = SurfaceTriangles::kFloatsPerCorner * sizeof(float);
  vertexAttribute(0, 3, GL_FLOAT, GL_FALSE, corner, 0);
  vertexAttribute(1, 3, GL_FLOAT, GL_FALSE, corner, 3 * sizeof(float));
  vertexAttribute(2, 3, GL_FLOAT, GL_FALSE, corner, 6 * sizeof(float));

  glGenVertexArrays(1, &overlayVao_);
  glGenBuffers(1, &overlayBuffer_);
  glBindVertexArray(overlayVao_);
  glBindBuffer(GL_ARRAY_BUFFER, overlayBuffer_);
  vertexAttribute(0, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), 0);
  vertexAttribute(1, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), 2 * sizeof(float));
  glBindVertexArray(0);
}

ParticleRenderer::~ParticleRenderer() {
  liquid_.reset();
  const GLuint buffers[] = {positionBuffer_, colourBuffer_, lineBuffer_,
                            overlayBuffer_,  liquidBuffer_, surfaceBuffer_};
  glDeleteBuffers(6, buffers);
  const GLuint arrays[] = {particleVao_, lineVao_, overlayVao_, liquidVao_, surfaceVao_};
  glDeleteVertexArrays(5, arrays);
}

void ParticleRenderer::reserve(std::size_t particles) {
  if (particles <= capacity_) return;
  // The fluid a GPU wrote is in the storage being replaced; its next write refills it.
  fluidOnGpu_ = 0;
  capacity_ = particles;
  glBindBuffer(GL_ARRAY_BUFFER, positionBuffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(4 * particles * sizeof(float)), nullptr,
               GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, colourBuffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(4 * particles), nullptr, GL_DYNAMIC_DRAW);
}

void ParticleRenderer::uploadPositions(const ParticleFrame& frame, std::size_t offset) {
  const std::size_t n = frame.size();
  if (n == 0) return;
  std::vector<float> positions(4 * n, 1.0f);
  for (std::size_t i = 0; i < n; ++i) std::copy_n(&frame.position[3 * i], 3, &positions[4 * i]);
  glBindBuffer(GL_ARRAY_BUFFER, positionBuffer_);
  glBufferSubData(GL_ARRAY_BUFFER, GLintptr(4 * offset * sizeof(float)),
                  GLsizeiptr(positions.size() * sizeof(float)), positions.data());
}

void ParticleRenderer::setParticles(const ParticleFrame& frame) {
  fluidOnGpu_ = 0;
  frame_ = frame;
  reserve(frame.size());
  uploadPositions(frame_, 0);
  liquidStale_ = true;
}

// The host frame's fluid alone, for the liquid view, once per frame that draws it.
void ParticleRenderer::uploadLiquid() {
  if (!liquidStale_) return;
  liquidStale_ = false;
  std::vector<float> fluid;
  for (std::size_t i = 0; i < frame_.size(); ++i)
    if (frame_.kind[i] == static_cast<std::uint8_t>(ParticleKind::Fluid)) {
      fluid.insert(fluid.end(), &frame_.position[3 * i], &frame_.position[3 * i] + 3);
      fluid.push_back(1.0f);
    }
  liquidCount_ = fluid.size() / 4;
  glBindBuffer(GL_ARRAY_BUFFER, liquidBuffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(fluid.size() * sizeof(float)), fluid.data(),
               GL_DYNAMIC_DRAW);
}

void ParticleRenderer::setObjectSurfaces(std::vector<ObjectSurfaceMesh> surfaces) {
  surfaces_ = std::move(surfaces);
  objectHasSurface_.clear();
  for (const ObjectSurfaceMesh& mesh : surfaces_) {
    if (mesh.object < 0) continue;
    if (objectHasSurface_.size() <= std::size_t(mesh.object))
      objectHasSurface_.resize(mesh.object + 1, 0);
    objectHasSurface_[mesh.object] = 1;
  }
}

void ParticleRenderer::setParticlesBehindFluid(std::size_t fluidCount, ValueRange fluidRange,
                                               const ParticleFrame& solids) {
  if (fluidCount + solids.size() > capacity_)
    throw std::invalid_argument("ParticleRenderer: " + std::to_string(fluidCount) +
                                " fluid particles and " + std::to_string(solids.size()) +
                                " others do not fit the " + std::to_string(capacity_) +
                                " reserved");
  fluidOnGpu_ = fluidCount;
  fluidOnGpuRange_ = fluidRange;
  frame_ = solids;
  liquidCount_ = 0;
  liquidStale_ = false;
  uploadPositions(frame_, fluidCount);
}

void ParticleRenderer::uploadColours(const DrawSettings& settings, const OrbitCamera& camera) {
  if (settings.range)
    range_ = *settings.range;
  else
    range_ = fluidOnGpu_ > 0 ? fluidOnGpuRange_ : rangeFromFrames({&frame_}, settings.colour);
  ParticleFilter show = settings.show;
  if (settings.look == Look::Liquid) show.fluid = false;  // drawn as a surface instead
  show.cut = cutPlane(settings, camera);
  std::vector<std::uint8_t> rgba = particleColours(frame_, settings.colour, range_, show);
  if (rgba.empty()) return;
  if (settings.objectSurfaces)  // drawn as their surfaces instead
    for (std::size_t i = 0; i < frame_.size(); ++i) {
      const std::int32_t object = frame_.object[i];
      if (frame_.kind[i] == static_cast<std::uint8_t>(ParticleKind::Object) && object >= 0 &&
          std::size_t(object) < objectHasSurface_.size() && objectHasSurface_[object])
        rgba[4 * i + 3] = 0;
    }
  glBindBuffer(GL_ARRAY_BUFFER, colourBuffer_);
  glBufferSubData(GL_ARRAY_BUFFER, GLintptr(4 * fluidOnGpu_), GLsizeiptr(rgba.size()), rgba.data());
}

void ParticleRenderer::draw(const OrbitCamera& camera, const DrawSettings& settings, int width,
                            int height) {
  glViewport(0, 0, width, height);
  glClearColor(settings.background.r, settings.background.g, settings.background.b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);

  const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
  const Mat4f view = camera.view();
  const Mat4f projection = camera.projection(aspect);
  const Mat4f viewProjection = multiply(projection, view);
  if (settings.showGrid)
    drawLines(gridOnBackFaces(settings.domain, settings.gridCellSize, camera.eye()), viewProjection,
              lineColour(settings.background, 0.10f));
  if (settings.showDomain || settings.showGrid)
    drawLines(boxEdges(settings.domain), viewProjection, lineColour(settings.background, 0.35f));
  if (particleCount() > 0) {
    uploadColours(settings, camera);
    drawParticles(view, projection, settings, height);
    if (settings.objectSurfaces && settings.show.objects && !surfaces_.empty())
      drawObjectSurfaces(view, projection, cutPlane(settings, camera));
    if (settings.look == Look::Liquid && settings.show.fluid)
      drawLiquid(view, projection, settings, width, height);
  }
  // The bar maps the fluid's colours, which the liquid look does not show.
  if (settings.showColourBar && usesRange(settings.colour) && settings.look == Look::Particles)
    drawColourBar(width, height);
  glBindVertexArray(0);
}

void ParticleRenderer::drawParticles(const Mat4f& view, const Mat4f& projection,
                                     const DrawSettings& settings, int height) {
  const GlProgram& program = programs_->spheres;
  glUseProgram(program.id());
  glUniformMatrix4fv(program.uniform("view"), 1, GL_FALSE, view.data());
  glUniformMatrix4fv(program.uniform("projection"), 1, GL_FALSE, projection.data());
  glUniform1f(program.uniform("radius"), settings.particleRadius);
  glUniform1f(program.uniform("viewportHeight"), static_cast<float>(height));
  const float length =
      std::sqrt(kLight[0] * kLight[0] + kLight[1] * kLight[1] + kLight[2] * kLight[2]);
  glUniform3f(program.uniform("lightDirection"), kLight[0] / length, kLight[1] / length,
              kLight[2] / length);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glBindVertexArray(particleVao_);
  // The liquid view leaves out the fluid a GPU wrote (its colours are the GPU's).
  const std::size_t first = settings.look == Look::Liquid ? fluidOnGpu_ : 0;
  glDrawArrays(GL_POINTS, static_cast<GLint>(first), static_cast<GLsizei>(particleCount() - first));
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
}

void ParticleRenderer::drawLiquid(const Mat4f& view, const Mat4f& projection,
                                  const DrawSettings& settings, int width, int height) {
  const bool onGpu = fluidOnGpu_ > 0;
  if (!onGpu) uploadLiquid();
  const std::size_t count = onGpu ? fluidOnGpu_ : liquidCount_;
  if (count == 0) return;
  if (!liquid_) liquid_ = std::make_unique<LiquidSurface>();
  liquid_->draw(onGpu ? particleVao_ : liquidVao_, 0, count, view, projection,
                kLiquidRadius * settings.particleRadius, 2.0f * settings.particleRadius,
                settings.liquid, settings.background, width, height);
}

void ParticleRenderer::drawObjectSurfaces(const Mat4f& view, const Mat4f& projection,
                                          const std::optional<CutPlane>& cut) {
  const SurfaceTriangles triangles = objectSurfaceTriangles(surfaces_, frame_);
  if (triangles.corners.empty()) return;
  const GlProgram& program = programs_->surfaces;
  glUseProgram(program.id());
  glUniformMatrix4fv(program.uniform("view"), 1, GL_FALSE, view.data());
  glUniformMatrix4fv(program.uniform("projection"), 1, GL_FALSE, projection.data());
  const float length =
      std::sqrt(kLight[0] * kLight[0] + kLight[1] * kLight[1] + kLight[2] * kLight[2]);
  glUniform3f(program.uniform("lightDirection"), kLight[0] / length, kLight[1] / length,
              kLight[2] / length);
  glUniform1i(program.uniform("cutaway"), cut ? 1 : 0);
  if (cut)
    glUniform4f(program.uniform("cutPlane"), cut->normal[0], cut->normal[1], cut->normal[2],
                dot(cut->normal, cut->point));
  glBindVertexArray(surfaceVao_);
  glBindBuffer(GL_ARRAY_BUFFER, surfaceBuffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(triangles.corners.size() * sizeof(float)),
               triangles.corners.data(), GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangles.triangleCount()));
}

void ParticleRenderer::drawLines(const std::vector<float>& lines, const Mat4f& viewProjection,
                                 const Rgb& colour) {
  if (lines.empty()) return;
  const GlProgram& program = programs_->lines;
  glUseProgram(program.id());
  glUniformMatrix4fv(program.uniform("viewProjection"), 1, GL_FALSE, viewProjection.data());
  glUniform4f(program.uniform("colour"), colour.r, colour.g, colour.b, 1.0f);
  glBindVertexArray(lineVao_);
  glBindBuffer(GL_ARRAY_BUFFER, lineBuffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(lines.size() * sizeof(float)), lines.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size() / 3));
}

void ParticleRenderer::drawColourBar(int width, int height) {
  const std::vector<float> triangles = colourBarTriangles(width, height);
  glUseProgram(programs_->overlay.id());
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(overlayVao_);
  glBindBuffer(GL_ARRAY_BUFFER, overlayBuffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(triangles.size() * sizeof(float)), triangles.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangles.size() / 5));
  glEnable(GL_DEPTH_TEST);
}

std::vector<std::uint8_t> readRgbPixels(int width, int height) {
  const std::size_t row = 3 * static_cast<std::size_t>(width);
  std::vector<std::uint8_t> pixels(row * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  // GL's rows start at the bottom; images start at the top.
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(pixels.begin() + std::ptrdiff_t(row) * y,
                     pixels.begin() + std::ptrdiff_t(row) * (y + 1),
                     pixels.begin() + std::ptrdiff_t(row) * (height - 1 - y));
  return pixels;
}

}  // namespace sph::render
