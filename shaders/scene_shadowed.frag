#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque scene with one light shadowed by a shadow map (set 2): the fraction of shadow-map
// texels around the point, within the PCF radius, that the point is not behind.
#include "include/shadow_view.glsl"

layout(set = 2, binding = 0) uniform texture2D shadow_depth;
layout(set = 2, binding = 1) uniform sampler shadow_sampler;
layout(set = 2, binding = 2) uniform ShadowBlock { ShadowView view; } shadow;

float light_visibility(int light, vec3 p) {
  if (light != int(shadow.view.params.w)) return 1.0;
  const vec4 clip = shadow.view.light_view_projection * vec4(p, 1.0);
  const vec3 ndc = clip.xyz / clip.w;
  const vec2 uv = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);  // NDC +y up, row 0 at the top
  if (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return 1.0;
  const ivec2 size = textureSize(sampler2D(shadow_depth, shadow_sampler), 0);
  const ivec2 centre = ivec2(uv * vec2(size));
  const int r = shadow.view.mode.x == 1 ? int(ceil(shadow.view.params.y)) : 0;
  float lit = 0.0, taps = 0.0;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const ivec2 texel = clamp(centre + ivec2(dx, dy), ivec2(0), size - 1);
      const float occluder = texelFetch(sampler2D(shadow_depth, shadow_sampler), texel, 0).r;
      lit += ndc.z - shadow.view.params.x <= occluder ? 1.0 : 0.0;
      taps += 1.0;
    }
  }
  return lit / taps;
}

#include "include/scene_shading.glsl"
