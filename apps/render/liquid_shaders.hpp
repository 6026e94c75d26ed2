// GLSL 3.30 sources of the liquid view's passes (liquid_surface.cpp).
#pragma once

namespace sph::render::shaders {

extern const char* const kLiquidSpriteVertex;       // the fluid's points as sphere sprites
extern const char* const kLiquidDepthFragment;      // each sphere's front, as eye-space depth
extern const char* const kLiquidThicknessFragment;  // each sphere's chord, summed
extern const char* const kFullScreenVertex;         // one triangle over the viewport
extern const char* const kLiquidSmoothFragment;     // the depth's narrow-range filter, one sweep
extern const char* const kLiquidShadeFragment;      // normals, absorption, refraction, reflection

}  // namespace sph::render::shaders
