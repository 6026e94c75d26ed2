// A linked GLSL program, compiled from source; needs a current OpenGL 3.3 core context.
#pragma once

#include <epoxy/gl.h>

#include <string>

namespace sph::render {

class GlProgram {
 public:
  // Throws std::runtime_error with the compiler's or linker's log, prefixed by `name`.
  GlProgram(const std::string& name, const char* vertexSource, const char* fragmentSource);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  GLuint id() const { return program_; }
  // -1 (which GL ignores) for a uniform the compiler removed as unused.
  GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

 private:
  GLuint program_ = 0;
};

}  // namespace sph::render
