#include "liquid_surface.hpp"

#include <epoxy/gl.h>

#include <cmath>
#include <stdexcept>

#include "gl_program.hpp"
#include "liquid_shaders.hpp"

namespace sph::render {

namespace {

// Light from the upper left, slightly in front, as the particle view's.
constexpr float kLight[3] = {-0.40f, 0.70f, 0.59f};

// The thickness is summed over wider spheres than the depth's: the same volume spread more
// evenly, without the grain of a disordered fluid's gaps.
constexpr float kThicknessSpread = 1.6f;

// A texture drawn into through a framebuffer of its own, its edges clamped.
void makeTarget(GLint format, GLenum channels, GLenum type, GLint filter, int width, int height,
                GLuint& texture, GLuint& framebuffer) {
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, format, width, height, 0, channels, type, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
}

// A texture of one float channel (eye depth, thickness), read back by exact texel.
struct FloatTarget {
  GLuint texture = 0, framebuffer = 0;

  void create(int width, int height, GLuint depthRenderbuffer) {
    makeTarget(GL_R32F, GL_RED, GL_FLOAT, GL_NEAREST, width, height, texture, framebuffer);
    if (depthRenderbuffer != 0)
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                depthRenderbuffer);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("liquid view: a float render target is not supported here");
  }
  void release() {
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
  }
  std::vector<float> read(int width, int height) const {
    std::vector<float> values(std::size_t(width) * std::size_t(height));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, values.data());
    return values;
  }
};

}  // namespace

struct LiquidSurface::Programs {
  GlProgram depth{"liquid depth", shaders::kLiquidSpriteVertex, shaders::kLiquidDepthFragment};
  GlProgram thickness{"liquid thickness", shaders::kLiquidSpriteVertex,
                      shaders::kLiquidThicknessFragment};
  GlProgram smooth{"liquid smoothing", shaders::kFullScreenVertex, shaders::kLiquidSmoothFragment};
  GlProgram shade{"liquid shading", shaders::kFullScreenVertex, shaders::kLiquidShadeFragment};
};

struct LiquidSurface::Targets {
  int width = 0, height = 0;
  GLuint depthRenderbuffer = 0;
  FloatTarget depth[2];  // the spheres' depth, then the smoothing's ping-pong
  FloatTarget thickness;
  GLuint sceneTexture = 0, sceneFramebuffer = 0;  // a copy of what lies behind the liquid

  Targets(int w, int h) : width(w), height(h) {
    glGenRenderbuffers(1, &depthRenderbuffer);
    glBindRenderbuffer(GL_RENDERBUFFER, depthRenderbuffer);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    depth[0].create(w, h, depthRenderbuffer);
    depth[1].create(w, h, 0);
    thickness.create(w, h, 0);
    // Sampled between texels: the refraction's offsets are fractions of a pixel.
    makeTarget(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_LINEAR, w, h, sceneTexture,
               sceneFramebuffer);
  }
  ~Targets() {
    depth[0].release();
    depth[1].release();
    thickness.release();
    glDeleteFramebuffers(1, &sceneFramebuffer);
    glDeleteTextures(1, &sceneTexture);
    glDeleteRenderbuffers(1, &depthRenderbuffer);
  }
};

LiquidSurface::LiquidSurface() : programs_(std::make_unique<Programs>()) {
  glGenVertexArrays(1, &emptyVertexArray_);
}

LiquidSurface::~LiquidSurface() {
  targets_.reset();
  glDeleteVertexArrays(1, &emptyVertexArray_);
}

void LiquidSurface::resize(int width, int height) {
  if (targets_ && targets_->width == width && targets_->height == height) return;
  targets_.reset();
  targets_ = std::make_unique<Targets>(width, height);
}

void LiquidSurface::draw(unsigned vertexArray, std::size_t first, std::size_t count,
                         const Mat4f& view, const Mat4f& projection, float radius, float spacing,
                         const LiquidStyle& style, Rgb background, int width, int height) {
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  resize(width, height);
  Targets& t = *targets_;

  // What lies behind the liquid, resolved from a multisampled target if it is one.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(target));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.sceneFramebuffer);
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);

  glViewport(0, 0, width, height);
  glEnable(GL_PROGRAM_POINT_SIZE);
  const auto spriteUniforms = [&](const GlProgram& program) {
    glUseProgram(program.id());
    glUniformMatrix4fv(program.uniform("view"), 1, GL_FALSE, view.data());
    glUniformMatrix4fv(program.uniform("projection"), 1, GL_FALSE, projection.data());
    glUniform1f(program.uniform("radius"), radius);
    glUniform1f(program.uniform("viewportHeight"), float(height));
  };
  const auto points = [&] {
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_POINTS, GLint(first), GLsizei(count));
  };

  glBindFramebuffer(GL_FRAMEBUFFER, t.depth[0].framebuffer);
  glClearColor(0, 0, 0, 0);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  spriteUniforms(programs_->depth);
  points();

  glBindFramebuffer(GL_FRAMEBUFFER, t.thickness.framebuffer);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  spriteUniforms(programs_->thickness);
  const float spread = kThicknessSpread * radius;
  glUniform1f(programs_->thickness.uniform("radius"), spread);
  const float sphere = 4.0f / 3.0f * 3.14159265f * spread * spread * spread;
  glUniform1f(programs_->thickness.uniform("chordScale"), spacing * spacing * spacing / sphere);
  points();
  glDisable(GL_BLEND);

  const GlProgram& smooth = programs_->smooth;
  glUseProgram(smooth.id());
  glUniform1i(smooth.uniform("depth"), 0);
  glUniform1f(smooth.uniform("reachWorld"), style.smoothingReach * radius);
  glUniform1f(smooth.uniform("focalPixels"), 0.5f * float(height) * projection[5]);
  glUniform1f(smooth.uniform("threshold"), 2.0f * radius);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(emptyVertexArray_);
  int from = 0;
  for (int pass = 0; pass < 2 * style.smoothingPasses; ++pass) {
    const bool across = pass % 2 == 0;
    glBindFramebuffer(GL_FRAMEBUFFER, t.depth[1 - from].framebuffer);
    glBindTexture(GL_TEXTURE_2D, t.depth[from].texture);
    glUniform2f(smooth.uniform("direction"), across ? 1.0f / float(width) : 0.0f,
                across ? 0.0f : 1.0f / float(height));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    from = 1 - from;
  }
  finalDepth_ = from;

  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
  glEnable(GL_DEPTH_TEST);
  const GlProgram& shade = programs_->shade;
  glUseProgram(shade.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, t.depth[from].texture);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, t.thickness.texture);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D, t.sceneTexture);
  glUniform1i(shade.uniform("depth"), 0);
  glUniform1i(shade.uniform("thickness"), 1);
  glUniform1i(shade.uniform("scene"), 2);
  glUniformMatrix4fv(shade.uniform("projection"), 1, GL_FALSE, projection.data());
  glUniform2f(shade.uniform("texel"), 1.0f / float(width), 1.0f / float(height));
  glUniform3f(shade.uniform("colour"), style.colour.r, style.colour.g, style.colour.b);
  glUniform3f(shade.uniform("absorption"), style.absorption.r, style.absorption.g,
              style.absorption.b);
  const float length =
      std::sqrt(kLight[0] * kLight[0] + kLight[1] * kLight[1] + kLight[2] * kLight[2]);
  glUniform3f(shade.uniform("lightDirection"), kLight[0] / length, kLight[1] / length,
              kLight[2] / length);
  // The sky the surface reflects: the background, lifted towards white.
  glUniform3f(shade.uniform("sky"), 0.55f + 0.45f * background.r, 0.58f + 0.42f * background.g,
              0.62f + 0.38f * background.b);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(0);
}

std::vector<float> LiquidSurface::smoothedDepth() const {
  if (!targets_) return {};
  return targets_->depth[finalDepth_].read(targets_->width, targets_->height);
}

std::vector<float> LiquidSurface::thickness() const {
  if (!targets_) return {};
  return targets_->thickness.read(targets_->width, targets_->height);
}

}  // namespace sph::render
