#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque scene: Lambertian reflection of every light (DESIGN.md units, unshadowed for
// now), plus ambient irradiance and emission. Surfaces are lit on the side seen.
#include "include/scene_uniforms.glsl"

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 radiance;

void main() {
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 e = frame.ambient_irradiance.rgb;
  for (int i = 0; i < frame.counts.x; ++i) e += irradiance(frame.lights[i], world_position, n);
  radiance = vec4(lambert(object.albedo.rgb, e) + object.emissive.rgb, 1.0);
}
