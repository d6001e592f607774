#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque scene with one light shadowed by a shadow map, dimmed by the media and tinted by the translucent casters through their maps
// (the same light view), and the sun dimmed by the cloud layer above through a
// cloud_shadow_map (set 2: the maps' 0–6, the cloud shadow's 7–9).
#include "include/cloud_shadow_set.glsl"
#include "include/opacity_shadow.glsl"
#include "include/translucent_shadow_lookup.glsl"
#include "include/shadow_lookup.glsl"

layout(set = 2, binding = 0) uniform texture2D shadow_depth;
layout(set = 2, binding = 1) uniform sampler shadow_sampler;
layout(set = 2, binding = 2) uniform ShadowBlock { ShadowView view; } shadow;
layout(set = 2, binding = 3) uniform texture3D media_shadow;
layout(set = 2, binding = 4) uniform sampler media_shadow_sampler;
layout(set = 2, binding = 5) uniform texture2D translucent_shadow;
layout(set = 2, binding = 6) uniform texture2D translucent_shadow_depth;

vec3 light_visibility(int light, vec3 p) {
  const float clouds = cloud_visibility(light, p);
  if (!shadows_light(shadow.view, light)) return vec3(clouds);
  return clouds * shadow_visibility(shadow_depth, shadow_sampler, shadow.view, p) *
         opacity_map_transmittance(media_shadow, media_shadow_sampler, shadow.view, p) *
         translucent_shadow_transmittance(translucent_shadow, translucent_shadow_depth, shadow_sampler, shadow.view, p);
}

#include "include/scene_shading.glsl"
