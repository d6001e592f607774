// The media's transmittance from a point toward a light, e^(−τ), τ in two parts:
// - the global fog and the height fog in closed form, always: a point or spot light sees
//   σt·d of the global fog and the height fog's closed-form optical depth along the
//   segment to it (media.glsl, the one height_fog uses for view rays); a directional light
//   the height fog's to infinity (infinite when the light travels level or upward) and no
//   global fog — its E is what reaches a point through the global fog (DESIGN.md, the CPU
//   reference's SceneMedia::optical_depth_to_infinity);
// - the local volumes, each σt × its chord on the segment to the light (`max_distance` m
//   toward a directional light) × its mean density there (media_average.glsl): exact for a
//   volume without edge fade or noise, the mean of `steps` points stratified over the chord
//   otherwise; not at all with 0 steps (or where an opacity shadow map, which holds the
//   volumes alone, stands in for it). optical_depth_along's march of equal steps serves
//   the opacity shadow map.
// CPU twin: physics/light_transmittance.h — change both.
#ifndef VOLGRAPH_LIGHT_TRANSMITTANCE_GLSL
#define VOLGRAPH_LIGHT_TRANSMITTANCE_GLSL
#include "lighting.glsl"
#include "media_average.glsl"
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

// The media a march sees: the local volumes alone (the fogs are in closed form).
MediaField local_volumes(MediaField field) {
  MediaField media = field;
  media.counts.yz = ivec2(0);
  return media;
}

// The global and height fog as the closed form sees them (σt 0 where a fog is absent): a
// few members of a MediaField, so that callers need not pass the whole field per light.
struct Fogs {
  vec3 fog_sigma_t;     // the global fog's σt (1/m)
  vec3 height_sigma_t;  // the height fog's σt at its base height (1/m)
  vec2 height;          // x base height (m), y falloff (1/m)
};

Fogs fogs_of(ivec4 counts, MediumCoefficients fog, MediumCoefficients height_fog, vec4 height) {
  return Fogs(counts.y != 0 ? fog.sigma_s_g.rgb + fog.sigma_a.rgb : vec3(0.0),
              counts.z != 0 ? height_fog.sigma_s_g.rgb + height_fog.sigma_a.rgb : vec3(0.0), height.xy);
}

// The closed-form part of τ: the global fog and the height fog from p toward `light`,
// `to_light` the unit direction from p toward it.
vec3 fog_optical_depth_to_light(Fogs fogs, Light light, vec3 p, vec3 to_light) {
  const bool directional = int(light.position_type.w) == LIGHT_DIRECTIONAL;
  if (directional) {
    if (all(equal(fogs.height_sigma_t, vec3(0.0)))) return vec3(0.0);
    return fogs.height_sigma_t * height_fog_unit_depth_to_infinity(fogs.height.y, fogs.height.x, p.y, to_light.y);
  }
  const float distance = length(light.position_type.xyz - p);
  const float unit_depth = height_fog_optical_depth(vec3(1.0), fogs.height.y, fogs.height.x, p.y, to_light.y, distance).r;
  return fogs.fog_sigma_t * distance + fogs.height_sigma_t * unit_depth;
}

// The local volumes' part of τ toward `light` from p: per volume, σt times the length of
// its chord on the segment to the light (`max_distance` m toward a directional one) times
// its mean density there (media_average.glsl) — exact for a volume without edge fade or
// noise, the mean of `samples` points stratified over the chord otherwise, each `jitter`
// (in [0, 1)) into its stratum; samples 0: none.
vec3 volumes_optical_depth_to_light(MediaField field, Light light, vec3 p, vec3 to_light, int samples, float max_distance,
                                    float jitter) {
  if (samples <= 0 || field.counts.x == 0) return vec3(0.0);
  const float len = light_march_length(light, p, max_distance);
  if (len <= 0.0) return vec3(0.0);
  vec3 optical_depth = vec3(0.0);
  for (int i = 0; i < field.counts.x; ++i) {
    const MediumVolume v = field.volumes[i];
    const float mean = volume_mean_density_sampled(v, p, to_light, 0.0, len, jitter - 0.5, samples);
    optical_depth += (v.medium.sigma_s_g.rgb + v.medium.sigma_a.rgb) * (mean * len);
  }
  return optical_depth;
}

// e^(−τ) of the closed-form part alone (what the scene pass dims surfaces by).
vec3 fog_transmittance_to_light(Fogs fogs, Light light, vec3 p, vec3 to_light) {
  return exp(-min(fog_optical_depth_to_light(fogs, light, p, to_light), vec3(MAX_EXPONENT)));
}

// e^(−τ) of the two parts together. `to_light`: the unit direction from p toward the light
// (−travel of light_arriving).
vec3 transmittance_to_light(Fogs fogs, MediaField field, Light light, vec3 p, vec3 to_light, int steps, float max_distance,
                            float jitter) {
  const vec3 optical_depth = fog_optical_depth_to_light(fogs, light, p, to_light) +
                             volumes_optical_depth_to_light(field, light, p, to_light, steps, max_distance, jitter);
  return exp(-min(optical_depth, vec3(MAX_EXPONENT)));
}

#endif
