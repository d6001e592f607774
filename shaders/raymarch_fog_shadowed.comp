#version 450
#extension GL_GOOGLE_include_directive : require
// raymarch_fog with one light shadowed by a shadow map (set 1). The march:
// shaders/include/raymarch_fog_body.glsl.
#include "include/shadow_lookup.glsl"

layout(set = 1, binding = 0) uniform texture2D shadow_depth;
layout(set = 1, binding = 1) uniform sampler shadow_sampler;
layout(set = 1, binding = 2) uniform ShadowBlock { ShadowView view; } shadow;

float light_visibility(int light, vec3 p) {
  if (!shadows_light(shadow.view, light)) return 1.0;
  return shadow_visibility(shadow_depth, shadow_sampler, shadow.view, p);
}

bool media_shadow_mapped(int light) { return false; }  // the march dims every light

#include "include/raymarch_fog_body.glsl"
