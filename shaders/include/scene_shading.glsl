// The scene pass's fragment body: ρ/π·Σ E·cos θ·V·T_fog + emission, T_fog the global and
// height fog's transmittance from the surface toward each light in closed form
// (light_transmittance.glsl, as the CPU reference dims surfaces). The including shader
// defines `float light_visibility(int light, vec3 p)` first (1 when unshadowed; a vec3
// where the local volumes between the light and p tint it, from an opacity shadow map).
#ifndef VOLGRAPH_SCENE_SHADING_GLSL
#define VOLGRAPH_SCENE_SHADING_GLSL
#include "light_transmittance.glsl"
#include "material_textures.glsl"
#include "scene_uniforms.glsl"

// E·cos θ from one light at p, normal n, through the fogs.
vec3 fogged_irradiance(Fogs fogs, Light light, vec3 p, vec3 n) {
  vec3 travel;
  const vec3 e = light_arriving(light, p, travel);
  const float cos_theta = max(dot(n, -travel), 0.0);
  if (cos_theta <= 0.0 || all(equal(e, vec3(0.0)))) return vec3(0.0);
  return e * cos_theta * fog_transmittance_to_light(fogs, light, p, -travel);
}

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 2) in vec2 texture_uv;
layout(location = 0) out vec4 radiance;

void main() {
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 e = frame.ambient_irradiance.rgb;
  const Fogs fogs = fogs_of(frame.media.counts, frame.media.fog, frame.media.height_fog, frame.media.height);
  for (int i = 0; i < frame.light_list.counts.x; ++i) {
    e += fogged_irradiance(fogs, frame.light_list.lights[i], world_position, n) * light_visibility(i, world_position);
  }
  const vec3 albedo = material_albedo(object.albedo.rgb, texture_uv);
  radiance = vec4(lambert(albedo, e) + material_emission(object.emissive.rgb, texture_uv), 1.0);
}

#endif
