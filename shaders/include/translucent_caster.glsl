// A translucent shadow caster's fragment (translucent_shadow.frag, translucent_shadow_depth.frag):
// the transmittance of the light crossing it, physics::surface_layer's — the function the
// translucency pass uses for light crossing the object (colour, coverage, Fresnel at the
// light's angle at its one interface, the path inside) — or false where it casts nothing
// here: an alpha-mask hole, a fragment behind the opaque shadow map's depth, or a solid's
// face turned away from the light (the solid is one layer, as the CPU reference's shadow rays cross it).
#ifndef VOLGRAPH_TRANSLUCENT_CASTER_GLSL
#define VOLGRAPH_TRANSLUCENT_CASTER_GLSL
#include "translucent_material_textures.glsl"
#include "object_uniforms.glsl"
#include "shadow_view.glsl"
#include "translucency.glsl"

layout(set = 0, binding = 0) uniform ShadowBlock { ShadowView view; } shadow;
layout(set = 0, binding = 1) uniform texture2D opaque_depth;  // shadow_map's depth
layout(set = 0, binding = 2) uniform sampler nearest;

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 2) in vec2 texture_uv;

// Unit vector from p toward the light: through the light's clip space (orthographic or
// perspective alike), from the far plane to the near one along p's ray.
vec3 toward_light(vec3 p) {
  const vec4 clip = shadow.view.light_view_projection * vec4(p, 1.0);
  const vec2 xy = clip.xy / clip.w;
  const vec4 near_point = shadow.view.clip_to_world * vec4(xy, 0.0, 1.0), far_point = shadow.view.clip_to_world * vec4(xy, 1.0, 1.0);
  return normalize(near_point.xyz / near_point.w - far_point.xyz / far_point.w);
}

// Whether the opaque map holds a surface nearer the light than this fragment.
bool behind_opaque(vec3 p) {
  const vec4 clip = shadow.view.light_view_projection * vec4(p, 1.0);
  const vec3 ndc = clip.xyz / clip.w;
  const ivec2 size = textureSize(sampler2D(opaque_depth, nearest), 0);
  const ivec2 texel = clamp(ivec2(vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5) * vec2(size)), ivec2(0), size - 1);
  return gl_FragCoord.z >= texelFetch(sampler2D(opaque_depth, nearest), texel, 0).r;
}

bool translucent_caster(out vec3 passed) {
  passed = vec3(1.0);
  // The textures first (implicit derivatives need uniform control flow: before any return).
  const vec3 albedo = material_albedo(object.albedo.rgb, texture_uv);
  const float texel_coverage = material_coverage(object.translucency.x, texture_uv);
  const float transmission = material_transmission(object.translucency.y, texture_uv);
  const float thickness = material_thickness(object.translucency.w, texture_uv);
  const int alpha_mode = int(object.alpha_test.x);
  if (alpha_mode == kAlphaMask && texel_coverage < object.alpha_test.y) return false;
  if (behind_opaque(world_position)) return false;
  const vec3 to_light = toward_light(world_position);
  const float facing = dot(normalize(world_normal), to_light);
  const int kind = int(object.attenuation.w);
  if (kind == kVolumeSolid && facing < 0.0) return false;  // its exit face: no second interface (KHR_materials_volume)
  const float cos_light = clamp(abs(facing), 0.0, 1.0);
  const float ior = object.translucency.z;
  // The path inside: none for a thin wall; the thickness at the refracted angle for a shell and
  // (a known limit: no chord to its back face from the light) a solid.
  const float inside = kind == kVolumeThinWalled ? 0.0 : shell_path_length(thickness, ior, cos_light);
  LayerInputs l;
  l.alpha = alpha_mode == kAlphaBlend ? texel_coverage : 1.0;
  l.transmission = transmission;
  l.albedo = albedo;
  l.emissive = vec3(0.0);
  l.irradiance = vec3(0.0);
  l.environment = vec3(0.0);
  l.reflectance = interface_reflectance(ior, cos_light);
  l.path_transmittance = exp(-object.attenuation.rgb * inside);
  passed = surface_layer(l).transmittance;
  return true;
}

#endif
