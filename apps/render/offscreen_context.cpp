#include "offscreen_context.hpp"

#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <mutex>

namespace sph::render {

namespace {

constexpr const char* kNeeds =
    "; rendering without a display needs EGL with Mesa's surfaceless platform "
    "(Debian: libegl1 libegl-mesa0 libgl1-mesa-dri)";

[[noreturn]] void unavailable(const std::string& what) {
  throw ContextUnavailable(what + kNeeds);
}

std::string eglErrorText(const char* call) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  return std::string(call) + " failed (EGL error " + code + ")";
}

// libepoxy aborts the process when it cannot load libEGL: look first, and fail politely.
void requireEglLibrary() {
  void* egl = dlopen("libEGL.so.1", RTLD_LAZY | RTLD_LOCAL);
  if (egl == nullptr) unavailable(std::string("cannot load libEGL.so.1: ") + dlerror());
  // Left loaded: libepoxy opens it again and keeps it for the process's life.
}

// The display stays initialised for the process's life, never terminated: every caller gets the
// same one from eglGetPlatformDisplayEXT, EGL counts no references (eglTerminate would end the
// contexts of every other user), and Mesa would unload and reload its driver each time.
std::once_flag displayInitialised;
bool displayReady = false;

bool hasExtension(const char* extensions, const char* name) {
  return extensions != nullptr && std::strstr(extensions, name) != nullptr;
}

}  // namespace

OffscreenContext::OffscreenContext(int width, int height) : width_(width), height_(height) {
  if (width < 1 || height < 1)
    throw std::invalid_argument("offscreen picture of " + std::to_string(width) + "x" +
                                std::to_string(height) + " pixels");
  requireEglLibrary();
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
    unavailable("EGL has no EGL_MESA_platform_surfaceless");
  EGLDisplay display =
      eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) unavailable(eglErrorText("eglGetPlatformDisplayEXT"));
  std::call_once(displayInitialised,
                 [&] { displayReady = eglInitialize(display, nullptr, nullptr) == EGL_TRUE; });
  if (!displayReady) unavailable("eglInitialize failed on the surfaceless platform");
  display_ = display;
  try {
    if (!eglBindAPI(EGL_OPENGL_API)) unavailable(eglErrorText("eglBindAPI(OpenGL)"));
    const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                       EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!eglChooseConfig(display, configAttributes, &config, 1, &configs) || configs < 1)
      unavailable("no EGL config renders OpenGL");
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                        3,
                                        EGL_CONTEXT_MINOR_VERSION,
                                        3,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context == EGL_NO_CONTEXT) unavailable(eglErrorText("eglCreateContext(OpenGL 3.3 core)"));
    context_ = context;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
      unavailable(eglErrorText("eglMakeCurrent without a surface"));
    createFramebuffers();
  } catch (...) {
    release();
    throw;
  }
}

OffscreenContext::~OffscreenContext() {
  release();
}

void OffscreenContext::release() noexcept {
  auto display = static_cast<EGLDisplay>(display_);
  if (display == nullptr) return;
  if (context_ != nullptr && drawFramebuffer_ != 0) {
    glDeleteFramebuffers(1, &drawFramebuffer_);
    glDeleteFramebuffers(1, &readFramebuffer_);
    glDeleteRenderbuffers(3, renderbuffers_);
  }
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_ != nullptr) eglDestroyContext(display, static_cast<EGLContext>(context_));
  // No eglTerminate: see displayInitialised.
  display_ = nullptr;
  context_ = nullptr;
}

void OffscreenContext::createFramebuffers() {
  GLint maxSize = 0, maxSamples = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  if (width_ > maxSize || height_ > maxSize)
    throw ContextUnavailable("a " + std::to_string(width_) + "x" + std::to_string(height_) +
                             " picture exceeds the driver's largest, " + std::to_string(maxSize) +
                             " pixels a side");
  samples_ = std::min(4, static_cast<int>(maxSamples));
  glGenRenderbuffers(3, renderbuffers_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width_, height_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width_,
                                   height_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[2]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);

  glGenFramebuffers(1, &drawFramebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, drawFramebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            renderbuffers_[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            renderbuffers_[1]);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw ContextUnavailable("the drawing framebuffer is incomplete");
  glGenFramebuffers(1, &readFramebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, readFramebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            renderbuffers_[2]);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw ContextUnavailable("the reading framebuffer is incomplete");
  bindForDrawing();
}

std::string OffscreenContext::description() const {
  const auto text = [](GLenum name) {
    const GLubyte* value = glGetString(name);
    return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
  };
  return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

void OffscreenContext::bindForDrawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, drawFramebuffer_);
}

void OffscreenContext::resolveForReading() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, drawFramebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, readFramebuffer_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, readFramebuffer_);
}

}  // namespace sph::render
