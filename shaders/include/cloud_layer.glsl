// The cloud layer's geometry and density on the GPU, shared by the passes that sample it
// (cloud_march.comp, cloud_shadow_map.comp): the planet's sphere, the altitude, the layer's
// spheres, and the density of cloud_density.h on cloud_noise's textures drifted by the wind
// and the curl (Schneider & Vos 2015; GPU Pro 7 §4.3). The including shader declares first:
// `params` with vec4 members layer (x bottom, y top altitude, z planet radius, w the altitude
// of world y = 0), cloud (x coverage, y type), scales (x shape tile, y detail tile, z curl
// distortion) and wind (xyz the noise's offset), and texture3D shape, detail, texture2D curl
// and sampler noise (linear, repeat). With CLOUD_WEATHER_MAP defined, also texture2D weather
// (cloud_weather_map's) and params.weather (x 1 / the map's size, yz its offset).
#ifndef VOLGRAPH_CLOUD_LAYER_GLSL
#define VOLGRAPH_CLOUD_LAYER_GLSL
#include "cloud_density.h"

// The planet's centre seen from the world's origin: straight below, the radius plus y = 0's altitude.
vec3 planet_centre() { return vec3(0.0, -(params.layer.z + params.layer.w), 0.0); }

// The altitude of p above the planet's sphere (m).
float altitude(vec3 p) { return length(p - planet_centre()) - params.layer.z; }

// Ray o + t·d (d unit) against the sphere of the planet's radius plus `sphere_altitude`,
// from an origin at altitude `origin_altitude`: the two roots (t0 ≤ t1), or none (false).
// c = |o|² − r² as (h_o − h_r)(|o| + r) and the roots by the stable quadratic: no
// cancellation at the planet's scale in float.
bool sphere_roots(vec3 o, vec3 d, float origin_altitude, float sphere_altitude, out float t0, out float t1) {
  const vec3 oc = o - planet_centre();
  const float r = params.layer.z + sphere_altitude;
  const float b = dot(oc, d);
  const float c = (origin_altitude - sphere_altitude) * (length(oc) + r);
  const float disc = b * b - c;
  if (disc < 0.0) return false;
  const float q = -(b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
  const float ra = q, rb = (q != 0.0) ? c / q : 0.0;
  t0 = min(ra, rb);
  t1 = max(ra, rb);
  return true;
}

// The noise's coordinates of p: horizontal position and altitude, drifted by the wind.
vec3 noise_point(vec3 p) { return vec3(p.x, altitude(p), p.z) + params.wind.xyz; }

// The coverage and type at p: the layer's, or with a weather map (Schneider & Vos 2015) the
// layer's coverage × the map's r and mix(the layer's type, g, a), the map bilinear and
// repeating at (p.xz + wind.xz + offset) / size: the weather drifts with the clouds.
#ifdef CLOUD_WEATHER_MAP
vec2 coverage_and_type(vec3 p) {
  const vec4 w = texture(sampler2D(weather, noise), (p.xz + params.wind.xz + params.weather.yz) * params.weather.x);
  return vec2(params.cloud.x * w.r, mix(params.cloud.y, w.g, w.a));
}
#else
vec2 coverage_and_type(vec3 p) { return params.cloud.xy; }
#endif

// The base density only (the coarse steps' test; GPU Pro 7 §4.3.3).
float base_density(vec3 p, float h) {
  const vec4 s = texture(sampler3D(shape, noise), noise_point(p) / params.scales.x);
  const vec2 here = coverage_and_type(p);
  return cloud_base_density(s, h, here.x, here.y);
}

// The full density: the base eroded by the curl-distorted detail (GPU Pro 7 §4.3.4).
float density(vec3 p) {
  const float h = cloud_height_fraction(altitude(p), params.layer.x, params.layer.y);
  const float base = base_density(p, h);
  if (base <= 0.0) return 0.0;
  const vec3 q = noise_point(p) / params.scales.y;
  const vec2 swirl = texture(sampler2D(curl, noise), q.xz).xy * 2.0 - 1.0;
  const vec4 d = texture(sampler3D(detail, noise), q + params.scales.z * vec3(swirl.x, 0.0, swirl.y) * (1.0 - h));
  return cloud_eroded_density(base, d, h);
}

#endif
