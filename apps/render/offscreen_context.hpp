// An OpenGL 3.3 core context with no window or display (EGL on Mesa's surfaceless platform),
// current on the creating thread, drawing into a framebuffer object of a given size: colour and
// depth, 4× multisampled where the driver allows, resolved for reading.
#pragma once

#include <stdexcept>
#include <string>

namespace sph::render {

// No offscreen context could be made; the message says what is missing.
class ContextUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OffscreenContext {
 public:
  // Makes the context current and binds the framebuffer for drawing. Throws ContextUnavailable.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa".
  std::string description() const;

  // Binds the framebuffer to draw into.
  void bindForDrawing() const;
  // Resolves the multisampled picture and binds it for reading (readRgbPixels).
  void resolveForReading() const;

 private:
  void createFramebuffers();
  void release() noexcept;

  int width_, height_;
  int samples_ = 0;
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  unsigned drawFramebuffer_ = 0, readFramebuffer_ = 0;
  unsigned renderbuffers_[3] = {0, 0, 0};  // colour and depth to draw into, colour to read
};

}  // namespace sph::render
