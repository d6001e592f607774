// Tone mapping of linear radiance. CPU twin: physics/tonemap.h (keep in step).
#ifndef VOLGRAPH_TONEMAP_GLSL
#define VOLGRAPH_TONEMAP_GLSL

#include "tonemap_codes.h"

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": x(ax + b) / (x(cx + d) + e), clamped.
vec3 tone_map_aces(vec3 x) {
  const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

// Reinhard et al. 2002, eq. 3: L / (1 + L), per channel.
vec3 tone_map_reinhard(vec3 x) { return x / (1.0 + x); }

vec3 tone_map(vec3 radiance, float exposure_ev, int op) {
  const vec3 x = max(radiance, vec3(0.0)) * exp2(exposure_ev);
  if (op == TONE_MAP_ACES) return tone_map_aces(x);
  if (op == TONE_MAP_REINHARD) return tone_map_reinhard(x);
  return x;
}

#endif
