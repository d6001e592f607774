// The scene pass's fragment body: ρ/π·Σ E·cos θ·V·T_fog + emission, T_fog the global and
// height fog's transmittance from the surface toward each light in closed form
// (light_transmittance.glsl, as the CPU reference dims surfaces). The including shader
// defines `float light_visibility(int light, vec3 p)` first (1 when unshadowed; a vec3
// where the local volumes between the light and p tint it, from an opacity shadow map).
#ifndef VOLGRAPH_SCENE_SHADING_GLSL
#define VOLGRAPH_SCENE_SHADING_GLSL
#include "material_textures.glsl"
#include "surface_irradiance.glsl"

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 2) in vec2 texture_uv;
layout(location = 0) out vec4 radiance;

void main() {
  // The textures first (implicit derivatives need uniform control flow: before any discard).
  const vec3 albedo = material_albedo(object.albedo.rgb, texture_uv);
  const vec3 emission = material_emission(object.emissive.rgb, texture_uv);
  const float coverage = material_coverage(object.translucency.x, texture_uv);
  // alphaMode mask: a texel of coverage below the cutoff is a hole.
  if (int(object.alpha_test.x) == kAlphaMask && coverage < object.alpha_test.y) discard;
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;
  const vec3 e = surface_irradiance(world_position, n);
  radiance = vec4(lambert(albedo, e) + emission, 1.0);
}

#endif
