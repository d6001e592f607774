// Volumetric shadows: the transmittance of the media from a point toward a light,
// e^(−∫σt), the optical depth estimated by a march of equal steps through
// media_field.glsl (σt at (k + jitter)·Δ, k = 0 … steps − 1, times Δ). Directional
// lights: up to `max_distance` m, with the global fog left out (a directional light's E
// is what reaches a point through it, DESIGN.md and the CPU reference); point and spot
// lights: up to the light. CPU twin: physics/light_transmittance.h — change both.
#ifndef VOLGRAPH_LIGHT_TRANSMITTANCE_GLSL
#define VOLGRAPH_LIGHT_TRANSMITTANCE_GLSL
#include "lighting.glsl"
#include "media_field.glsl"

// How far the march toward `light` from `p` goes (m).
float light_march_length(Light light, vec3 p, float max_distance) {
  if (int(light.position_type.w) == LIGHT_DIRECTIONAL) return max_distance;
  return length(light.position_type.xyz - p);
}

// ∫σt over `len` m from p along unit `direction`, by `steps` equal steps sampled at
// (k + jitter)·Δ (the midpoint rule for jitter 0.5).
vec3 optical_depth_along(MediaField media, vec3 p, vec3 direction, float len, int steps, float jitter) {
  if (steps <= 0) return vec3(0.0);
  const float step_length = len / float(steps);
  vec3 optical_depth = vec3(0.0);
  for (int k = 0; k < steps; ++k) {
    const MediaSample s = sample_media(media, p + (float(k) + jitter) * step_length * direction);
    optical_depth += (s.sigma_s + s.sigma_a) * step_length;
  }
  return optical_depth;
}

// The media a march toward `light` sees: a directional light's without the global fog.
MediaField media_toward_light(MediaField field, Light light) {
  MediaField media = field;
  if (int(light.position_type.w) == LIGHT_DIRECTIONAL) media.counts.y = 0;
  return media;
}

// `to_light`: the unit direction from p toward the light (−travel of light_arriving);
// `jitter` in [0, 1): where inside each step σt is sampled.
vec3 transmittance_to_light(MediaField field, Light light, vec3 p, vec3 to_light, int steps, float max_distance, float jitter) {
  if (steps <= 0) return vec3(1.0);
  const vec3 optical_depth = optical_depth_along(media_toward_light(field, light), p, to_light,
                                                 light_march_length(light, p, max_distance), steps, jitter);
  return exp(-min(optical_depth, vec3(MAX_EXPONENT)));
}

#endif
