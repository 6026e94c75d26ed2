// The liquid view: the fluid's particles drawn as one liquid surface in screen space (van der
// Laan, Green & Sainz, "Screen Space Fluid Rendering with Curvature Flow", 2009). The spheres'
// nearest depths are smoothed by a narrow-range filter into a surface, its normals taken from
// the smoothed depth; the spheres' summed chords give the liquid's thickness along each ray,
// through which what lies behind is absorbed (Beer–Lambert) and refracted; the surface
// reflects the sky by Fresnel's law and takes a highlight. Drawn over whatever the bound
// framebuffer holds, whose depth hides the liquid behind walls and objects. Needs a current
// OpenGL 3.3 core context.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "camera.hpp"
#include "liquid_style.hpp"

namespace sph::render {

class LiquidSurface {
 public:
  // Compiles the shaders; throws std::runtime_error when they do not compile.
  LiquidSurface();
  ~LiquidSurface();
  LiquidSurface(const LiquidSurface&) = delete;
  LiquidSurface& operator=(const LiquidSurface&) = delete;

  // The `count` points from `first` of `vertexArray` (attribute 0: x, y, z, w), particles of
  // a lattice `spacing` apart drawn as spheres of `radius`, into the bound draw framebuffer's
  // (0, 0, width, height).
  void draw(unsigned vertexArray, std::size_t first, std::size_t count, const Mat4f& view,
            const Mat4f& projection, float radius, float spacing, const LiquidStyle& style,
            Rgb background, int width, int height);

  // The last draw's smoothed depth in front of the eye (m; 0 where no liquid), and the
  // liquid's thickness along each ray (m): width × height each, the bottom row first.
  std::vector<float> smoothedDepth() const;
  std::vector<float> thickness() const;

 private:
  struct Targets;
  void resize(int width, int height);

  struct Programs;
  std::unique_ptr<Programs> programs_;
  std::unique_ptr<Targets> targets_;
  unsigned emptyVertexArray_ = 0;
  int finalDepth_ = 0;  // which of the two smoothing targets the last draw ended in
};

}  // namespace sph::render
