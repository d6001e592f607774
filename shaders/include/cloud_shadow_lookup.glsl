// The cloud layer's transmittance toward the sun at world point p, from cloud_shadow_map's
// optical depth τ (r of its map) over its placement `view` (cloud_shadow_view.h): p carried
// along to_sun onto the layer's bottom plane, that point's τ (bilinear), exp(−τ). Points
// that land outside the map are unshadowed (1); a sun at or below the horizon gives 0 (the
// planet's shadow; the map holds a large τ there too). Points above the plane are carried
// back down to it (the layer between them and the plane is counted: an approximation).
#ifndef VOLGRAPH_CLOUD_SHADOW_LOOKUP_GLSL
#define VOLGRAPH_CLOUD_SHADOW_LOOKUP_GLSL
#include "cloud_shadow_view.h"

// The map's uv of the point where the ray from p toward the sun meets the bottom plane.
vec2 cloud_shadow_uv(CloudShadowView view, vec3 p) {
  const float s = (view.plane.y - p.y) / view.to_sun.y;
  const vec3 q = p + s * view.to_sun.xyz;
  return (q.xz - view.plane.xz) / view.plane.w + 0.5;
}

float cloud_shadow_transmittance(texture2D optical_depth, sampler s, CloudShadowView view, vec3 p) {
  if (view.to_sun.y <= 0.0) return 0.0;
  const vec2 uv = cloud_shadow_uv(view, p);
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
  return exp(-textureLod(sampler2D(optical_depth, s), uv, 0.0).r);  // level 0: no derivatives in non-uniform flow (WGSL)
}

#endif
