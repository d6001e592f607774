// The scene pass's fragment body. The including shader defines
// `float light_visibility(int light, vec3 p)` first (1 when unshadowed; a vec3 where the
// media between the light and p tint it).
#ifndef VOLGRAPH_SCENE_SHADING_GLSL
#define VOLGRAPH_SCENE_SHADING_GLSL
#include "material_textures.glsl"
#include "scene_uniforms.glsl"

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 2) in vec2 texture_uv;
layout(location = 0) out vec4 radiance;

void main() {
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 e = frame.ambient_irradiance.rgb;
  for (int i = 0; i < frame.light_list.counts.x; ++i) {
    e += irradiance(frame.light_list.lights[i], world_position, n) * light_visibility(i, world_position);
  }
  const vec3 albedo = material_albedo(object.albedo.rgb, texture_uv);
  radiance = vec4(lambert(albedo, e) + material_emission(object.emissive.rgb, texture_uv), 1.0);
}

#endif
