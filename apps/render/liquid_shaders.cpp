#include "liquid_shaders.hpp"

namespace sph::render::shaders {

const char* const kLiquidSpriteVertex = R"(#version 330 core
layout(location = 0) in vec4 position;
uniform mat4 view;
uniform mat4 projection;
uniform float radius;          // world units
uniform float viewportHeight;  // pixels
out vec3 eyeCentre;
void main() {
  vec4 eye = view * vec4(position.xyz, 1.0);
  eyeCentre = eye.xyz;
  gl_Position = projection * eye;
  gl_PointSize = viewportHeight * projection[1][1] * radius / -eye.z;
}
)";

const char* const kLiquidDepthFragment = R"(#version 330 core
in vec3 eyeCentre;
uniform mat4 projection;
uniform float radius;
out float eyeDepth;  // distance in front of the eye along its axis, m; 0 where no liquid
void main() {
  vec2 xy = 2.0 * gl_PointCoord - 1.0;
  xy.y = -xy.y;
  float r2 = dot(xy, xy);
  if (r2 > 1.0) discard;
  vec3 front = eyeCentre + radius * vec3(xy, sqrt(1.0 - r2));
  vec4 clip = projection * vec4(front, 1.0);
  gl_FragDepth = 0.5 * clip.z / clip.w + 0.5;
  eyeDepth = -front.z;
}
)";

const char* const kLiquidThicknessFragment = R"(#version 330 core
in vec3 eyeCentre;
uniform float radius;
uniform float chordScale;  // a particle's volume over its sphere's: the spheres overlap
out float thickness;       // m of liquid along the ray, summed over the spheres it crosses
void main() {
  vec2 xy = 2.0 * gl_PointCoord - 1.0;
  float r2 = dot(xy, xy);
  if (r2 > 1.0) discard;
  thickness = chordScale * 2.0 * radius * sqrt(1.0 - r2);
}
)";

const char* const kFullScreenVertex = R"(#version 330 core
out vec2 uv;
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  uv = corner;
  gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}
)";

// One sweep of the narrow-range filter (after Truong & Yuksel, "A Narrow-Range Filter for
// Screen-Space Fluid Rendering", 2018): a Gaussian over the neighbours along `direction`, in
// which a neighbour far behind (another layer) is left out and one far in front (an edge) is
// taken at the threshold's depth, so that the filter flattens the spheres' bumps without
// pulling a silhouette back or bridging layers.
const char* const kLiquidSmoothFragment = R"(#version 330 core
in vec2 uv;
uniform sampler2D depth;
uniform vec2 direction;    // one texel along x or y
uniform float reachWorld;  // the filter's half width, m
uniform float focalPixels; // pixels per unit of x/z at the image's centre
uniform float threshold;   // m: the depth range that counts as the same surface
out float smoothed;
void main() {
  float z = texture(depth, uv).r;
  if (z <= 0.0) { smoothed = 0.0; return; }
  float reach = clamp(reachWorld * focalPixels / z, 1.0, 24.0);
  int taps = int(ceil(reach));
  float sigma = 0.5 * reach;
  float sum = 0.0, weights = 0.0;
  for (int k = -taps; k <= taps; ++k) {
    float zk = texture(depth, uv + float(k) * direction).r;
    if (zk <= 0.0) continue;
    float d = (zk - z) / threshold;
    float w = exp(-float(k * k) / (2.0 * sigma * sigma) - 0.5 * d * d);
    sum += w * zk;
    weights += w;
  }
  smoothed = sum / weights;
}
)";

const char* const kLiquidShadeFragment = R"(#version 330 core
in vec2 uv;
uniform sampler2D depth;      // smoothed eye depth, m
uniform sampler2D thickness;  // m
uniform sampler2D scene;      // what was drawn before the liquid
uniform mat4 projection;
uniform vec2 texel;
uniform vec3 colour;          // the liquid's, deep
uniform vec3 absorption;      // 1/m
uniform vec3 lightDirection;  // eye space, toward the light
uniform vec3 sky;             // what the surface reflects
out vec4 fragColour;

vec3 eyePosition(vec2 at, float z) {
  vec2 ndc = 2.0 * at - 1.0;
  return vec3(ndc.x * z / projection[0][0], ndc.y * z / projection[1][1], -z);
}

// The smaller of the two one-sided differences: across a silhouette the far side belongs to
// another surface.
vec3 tangent(vec3 p, vec2 step) {
  float zf = texture(depth, uv + step).r, zb = texture(depth, uv - step).r;
  vec3 forward = zf > 0.0 ? eyePosition(uv + step, zf) - p : vec3(0.0);
  vec3 backward = zb > 0.0 ? p - eyePosition(uv - step, zb) : vec3(0.0);
  if (zf <= 0.0) return backward;
  if (zb <= 0.0) return forward;
  return abs(forward.z) < abs(backward.z) ? forward : backward;
}

void main() {
  float z = texture(depth, uv).r;
  if (z <= 0.0) discard;
  vec3 p = eyePosition(uv, z);
  vec3 dx = tangent(p, vec2(texel.x, 0.0)), dy = tangent(p, vec2(0.0, texel.y));
  vec3 n = normalize(cross(dx, dy));
  if (dot(n, p) > 0.0) n = -n;
  vec3 toEye = normalize(-p);
  float t = texture(thickness, uv).r;
  vec3 through = exp(-absorption * t);
  vec3 behind = texture(scene, uv + n.xy * 0.03 * (1.0 - through.g)).rgb;
  float diffuse = max(dot(n, lightDirection), 0.0);
  // The light the liquid scatters back grows with its opacity; what comes through from
  // behind is tinted by the absorption of each channel.
  float opacity = 1.0 - exp(-dot(absorption, vec3(1.0 / 3.0)) * t);
  vec3 body = behind * through + colour * (0.35 + 0.65 * diffuse) * opacity;
  float cosine = clamp(dot(n, toEye), 0.0, 1.0);
  float fresnel = 0.02 + 0.98 * pow(1.0 - cosine, 5.0);
  vec3 reflected = sky * (0.6 + 0.4 * reflect(-toEye, n).y);
  float specular = pow(max(dot(n, normalize(lightDirection + toEye)), 0.0), 96.0);
  fragColour = vec4(mix(body, reflected, fresnel) + vec3(0.6 * specular), 1.0);
  vec4 clip = projection * vec4(p, 1.0);
  gl_FragDepth = 0.5 * clip.z / clip.w + 0.5;
}
)";

}  // namespace sph::render::shaders
