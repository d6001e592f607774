// Reading the sky from the atmosphere's LUTs for a view direction in world space: its
// latitude and azimuth from the sun around the camera into the sky-view LUT (Hillaire 2020
// §5.3), and the sun's disk, E / (π sin²α) within its angular radius α, through the
// transmittance LUT. CPU twin: physics/atmosphere_sky.h (sky_view_direction,
// sun_disk_radiance) — change both together.
#ifndef VOLGRAPH_ATMOSPHERE_SKY_LOOKUP_GLSL
#define VOLGRAPH_ATMOSPHERE_SKY_LOOKUP_GLSL

#include "atmosphere_transmittance_lookup.glsl"

// The camera in the planet's frame.
struct SkyFrame {
  vec3 up;          // its local zenith
  float r;          // its radius (at most the top's)
  vec3 toward_sun;  // unit
  float mu_s;       // the sun's zenith cosine there
};

// A world direction as the sky-view LUT holds it: (its zenith cosine, the cosine of its
// azimuth from the sun's).
vec2 sky_view_direction(SkyFrame f, vec3 direction) {
  const float mu = clamp(dot(direction, f.up), -1.0, 1.0);
  const vec3 across = direction - mu * f.up, sun_across = f.toward_sun - f.mu_s * f.up;
  const float lengths = length(across) * length(sun_across);
  return vec2(mu, lengths > 1e-12 ? clamp(dot(across, sun_across) / lengths, -1.0, 1.0) : 1.0);
}

vec3 sky_view_lookup(AtmosphereParameters a, texture2D sky_view, sampler linear, SkyFrame f, vec3 direction) {
  const ivec2 size = textureSize(sampler2D(sky_view, linear), 0);
  return texture(sampler2D(sky_view, linear), sky_view_lut_uv(a, f.r, sky_view_direction(f, direction), size)).rgb;
}

// Per unit E: 1 / (π sin²α) within the disk (a uniform disk of angular radius α gives
// E = L π sin²α), times the transmittance toward the sun; 0 outside it or below the ground.
vec3 sun_disk_radiance(AtmosphereParameters a, texture2D transmittance_lut, sampler nearest, SkyFrame f, vec3 direction,
                       float angular_radius) {
  if (dot(direction, f.toward_sun) < cos(angular_radius)) return vec3(0.0);
  const float mu = dot(direction, f.up);
  if (ray_hits_ground(a, f.r, mu)) return vec3(0.0);
  const float s = sin(angular_radius);
  return transmittance_lookup(a, transmittance_lut, nearest, f.r, mu) / (ATMOSPHERE_PI * s * s);
}

#endif
