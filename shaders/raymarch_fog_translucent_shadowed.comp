#version 450
#extension GL_GOOGLE_include_directive : require
// raymarch_fog with one light shadowed by a shadow map and tinted by the translucent casters
// between it and each sample, through a translucent_shadow_map of the same light view
// (set 1; RTR4 §14.5.1). The march: shaders/include/raymarch_fog_body.glsl.
#include "include/shadow_lookup.glsl"
#include "include/translucent_shadow_lookup.glsl"

layout(set = 1, binding = 0) uniform texture2D shadow_depth;
layout(set = 1, binding = 1) uniform sampler shadow_sampler;
layout(set = 1, binding = 2) uniform ShadowBlock { ShadowView view; } shadow;
layout(set = 1, binding = 5) uniform texture2D translucent_shadow;
layout(set = 1, binding = 6) uniform texture2D translucent_shadow_depth;

vec3 light_visibility(int light, vec3 p) {
  if (!shadows_light(shadow.view, light)) return vec3(1.0);
  return shadow_visibility(shadow_depth, shadow_sampler, shadow.view, p) *
         translucent_shadow_transmittance(translucent_shadow, translucent_shadow_depth, shadow_sampler, shadow.view, p);
}

bool media_shadow_mapped(int light) { return false; }  // the march dims every light

#include "include/raymarch_fog_body.glsl"
