// The transmittance of the translucent casters between world point p and the light of a
// translucent_shadow_map (its coloured transmittance and the nearest caster's depth, in the
// light view `view` of the shadow_map it was drawn over): the mean over the PCF taps of
// shadow_visibility of the texel's transmittance where p lies behind the texel's nearest
// caster, else 1 (p in front of the glass, or beside it). Points outside the map: 1.
#ifndef VOLGRAPH_TRANSLUCENT_SHADOW_LOOKUP_GLSL
#define VOLGRAPH_TRANSLUCENT_SHADOW_LOOKUP_GLSL
#include "shadow_filter_codes.h"
#include "shadow_view.glsl"

vec3 translucent_shadow_transmittance(texture2D transmittance, texture2D caster_depth, sampler s, ShadowView view, vec3 p) {
  const vec4 clip = view.light_view_projection * vec4(p, 1.0);
  const vec3 ndc = clip.xyz / clip.w;
  const vec2 uv = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);  // NDC +y up, row 0 at the top
  if (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return vec3(1.0);
  const ivec2 size = textureSize(sampler2D(caster_depth, s), 0);
  const ivec2 centre = ivec2(uv * vec2(size));
  const int r = view.mode.x == SHADOW_FILTER_PCF ? int(ceil(view.params.y)) : 0;
  vec3 passed = vec3(0.0);
  float taps = 0.0;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const ivec2 texel = clamp(centre + ivec2(dx, dy), ivec2(0), size - 1);
      const bool behind = ndc.z - view.params.x > texelFetch(sampler2D(caster_depth, s), texel, 0).r;
      passed += behind ? texelFetch(sampler2D(transmittance, s), texel, 0).rgb : vec3(1.0);
      taps += 1.0;
    }
  }
  return passed / taps;
}

#endif
