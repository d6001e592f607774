#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque scene with one light shadowed by a shadow map and the sun dimmed by the cloud layer
// above through a cloud_shadow_map (set 2: the shadow map's 0–2, the cloud shadow's 7–9).
#include "include/cloud_shadow_set.glsl"
#include "include/shadow_lookup.glsl"

layout(set = 2, binding = 0) uniform texture2D shadow_depth;
layout(set = 2, binding = 1) uniform sampler shadow_sampler;
layout(set = 2, binding = 2) uniform ShadowBlock { ShadowView view; } shadow;

float light_visibility(int light, vec3 p) {
  const float mapped = shadows_light(shadow.view, light) ? shadow_visibility(shadow_depth, shadow_sampler, shadow.view, p) : 1.0;
  return mapped * cloud_visibility(light, p);
}

#include "include/scene_shading.glsl"
