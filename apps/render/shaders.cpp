#include "shaders.hpp"

namespace sph::render::shaders {

const char* const kSphereVertex = R"(#version 330 core
layout(location = 0) in vec4 position;  // xyz; w is free for whoever writes the buffer
layout(location = 1) in vec4 colour;    // alpha 0: hidden
uniform mat4 view;
uniform mat4 projection;
uniform float radius;          // world units
uniform float viewportHeight;  // pixels
out vec3 sphereColour;
out vec3 eyeCentre;
void main() {
  vec4 eye = view * vec4(position.xyz, 1.0);
  eyeCentre = eye.xyz;
  sphereColour = colour.rgb;
  if (colour.a == 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: culled
    gl_PointSize = 1.0;
    return;
  }
  gl_Position = projection * eye;
  // The sphere's diameter in pixels at its distance.
  gl_PointSize = viewportHeight * projection[1][1] * radius / -eye.z;
}
)";

const char* const kSphereFragment = R"(#version 330 core
in vec3 sphereColour;
in vec3 eyeCentre;
uniform mat4 projection;
uniform float radius;
uniform vec3 lightDirection;  // eye space, toward the light, unit length
out vec4 fragColour;
void main() {
  vec2 xy = 2.0 * gl_PointCoord - 1.0;
  xy.y = -xy.y;  // gl_PointCoord starts at the sprite's top
  float r2 = dot(xy, xy);
  if (r2 > 1.0) discard;
  vec3 normal = vec3(xy, sqrt(1.0 - r2));
  // The depth of the sphere's front surface, so that spheres intersect as spheres do.
  vec4 clip = projection * vec4(eyeCentre + radius * normal, 1.0);
  gl_FragDepth = 0.5 * clip.z / clip.w + 0.5;
  float diffuse = max(dot(normal, lightDirection), 0.0);
  float specular = pow(max(dot(normal, normalize(lightDirection + vec3(0.0, 0.0, 1.0))), 0.0), 48.0);
  // Coverage falls off over the rim's last pixel: smooth edges under multisampling.
  float rim = sqrt(r2);
  float coverage = clamp((1.0 - rim) / max(fwidth(rim), 1e-4), 0.0, 1.0);
  fragColour = vec4(sphereColour * (0.28 + 0.72 * diffuse) + vec3(0.22 * specular), coverage);
}
)";

const char* const kSurfaceVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
uniform mat4 view;
uniform mat4 projection;
out vec3 worldPosition;
out vec3 eyeNormal;
out vec3 surfaceColour;
void main() {
  worldPosition = position;
  eyeNormal = mat3(view) * normal;  // the view turns and moves, never scales
  surfaceColour = colour;
  gl_Position = projection * view * vec4(position, 1.0);
}
)";

const char* const kSurfaceFragment = R"(#version 330 core
in vec3 worldPosition;
in vec3 eyeNormal;
in vec3 surfaceColour;
uniform vec3 lightDirection;  // eye space, toward the light, unit length
uniform vec4 cutPlane;        // world: xyz the normal toward the side kept, w its offset
uniform bool cutaway;
out vec4 fragColour;
void main() {
  if (cutaway && dot(cutPlane.xyz, worldPosition) < cutPlane.w) discard;
  // The inside of a vessel shows through the cutaway and through tears: light both faces.
  vec3 normal = normalize(gl_FrontFacing ? eyeNormal : -eyeNormal);
  float diffuse = max(dot(normal, lightDirection), 0.0);
  float specular = pow(max(dot(normal, normalize(lightDirection + vec3(0.0, 0.0, 1.0))), 0.0), 48.0);
  float inside = gl_FrontFacing ? 1.0 : 0.6;  // the inner face a little darker
  fragColour = vec4(inside * (surfaceColour * (0.28 + 0.72 * diffuse) + vec3(0.22 * specular)), 1.0);
}
)";

const char* const kLineVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 viewProjection;
void main() { gl_Position = viewProjection * vec4(position, 1.0); }
)";

const char* const kLineFragment = R"(#version 330 core
uniform vec4 colour;
out vec4 fragColour;
void main() { fragColour = colour; }
)";

const char* const kOverlayVertex = R"(#version 330 core
layout(location = 0) in vec2 position;  // normalised device coordinates
layout(location = 1) in vec3 colour;
out vec3 vertexColour;
void main() {
  vertexColour = colour;
  gl_Position = vec4(position, 0.0, 1.0);
}
)";

const char* const kOverlayFragment = R"(#version 330 core
in vec3 vertexColour;
out vec4 fragColour;
void main() { fragColour = vec4(vertexColour, 1.0); }
)";

}  // namespace sph::render::shaders
