// Weighted blended OIT's resolve (McGuire & Bavoil 2013), onto the colour behind in two
// draws: × revealage (the layers' transmittances multiplied: e^− of their summed optical
// depths), then + the weighted mean
// radiance Σ w·radiance / Σ w·opacity times the coverage the layers took, 1 − mean
// revealage. One layer comes back exactly: radiance/opacity · opacity.
#ifndef VOLGRAPH_OIT_RESOLVE_GLSL
#define VOLGRAPH_OIT_RESOLVE_GLSL

layout(set = 0, binding = 0) uniform texture2D oit_accumulation;
layout(set = 0, binding = 1) uniform texture2D oit_optical_depth;
layout(set = 0, binding = 2) uniform sampler nearest;

vec3 revealage_at(ivec2 px) { return exp(-texelFetch(sampler2D(oit_optical_depth, nearest), px, 0).rgb); }

vec3 mean_radiance_at(ivec2 px) {
  const vec4 sum = texelFetch(sampler2D(oit_accumulation, nearest), px, 0);
  const vec3 revealage = revealage_at(px);
  const float coverage = 1.0 - (revealage.r + revealage.g + revealage.b) / 3.0;
  return sum.a > 1e-6 ? sum.rgb / sum.a * coverage : vec3(0.0);
}

#endif
