// The GLSL 3.30 core sources of the renderer's programs.
#pragma once

namespace sph::render::shaders {

// Particles as point sprites shaded as spheres, writing each sphere's true depth.
extern const char* const kSphereVertex;
extern const char* const kSphereFragment;
// Objects' surfaces: triangles lit on both faces, cut away on the camera's side when asked.
extern const char* const kSurfaceVertex;
extern const char* const kSurfaceFragment;
// Lines in world space (domain box, grid) in one colour.
extern const char* const kLineVertex;
extern const char* const kLineFragment;
// Flat 2D triangles in normalised device coordinates with a colour per vertex (colour bar).
extern const char* const kOverlayVertex;
extern const char* const kOverlayFragment;

}  // namespace sph::render::shaders
