// Visibility of world point p from the light a shadow map was rendered for: the
// fraction of shadow-map texels around p's projection, within the PCF radius, that p is
// not behind (one texel without PCF). Points outside the map are lit. Shared by every
// pass that samples a shadow_map.
#ifndef VOLGRAPH_SHADOW_LOOKUP_GLSL
#define VOLGRAPH_SHADOW_LOOKUP_GLSL
#include "shadow_filter_codes.h"
#include "shadow_view.glsl"

float shadow_visibility(texture2D shadow_depth, sampler shadow_sampler, ShadowView view, vec3 p) {
  const vec4 clip = view.light_view_projection * vec4(p, 1.0);
  const vec3 ndc = clip.xyz / clip.w;
  const vec2 uv = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);  // NDC +y up, row 0 at the top
  if (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return 1.0;
  const ivec2 size = textureSize(sampler2D(shadow_depth, shadow_sampler), 0);
  const ivec2 centre = ivec2(uv * vec2(size));
  const int r = view.mode.x == SHADOW_FILTER_PCF ? int(ceil(view.params.y)) : 0;
  float lit = 0.0, taps = 0.0;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const ivec2 texel = clamp(centre + ivec2(dx, dy), ivec2(0), size - 1);
      const float occluder = texelFetch(sampler2D(shadow_depth, shadow_sampler), texel, 0).r;
      lit += ndc.z - view.params.x <= occluder ? 1.0 : 0.0;
      taps += 1.0;
    }
  }
  return lit / taps;
}

// Whether `view` shadows light `light` (the map is rendered for one light).
bool shadows_light(ShadowView view, int light) { return light == int(view.params.w); }

#endif
