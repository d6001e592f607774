// What the camera sees where no surface of the scene is, by a march along the pixel's own
// ray (Hillaire 2020's RenderSkyRayMarching path, no sky-view LUT), per unit E: a camera
// above the atmosphere starts where its ray enters the top (MoveToTopAtmosphere) and sees
// black space and the sun's unattenuated disk where it misses it; the air's in-scattering
// along the ray (include/atmosphere_sky.glsl scattering_along, T_sun and Ψ_ms from their
// LUTs); where the ray ends on the ground, the ground's radiance times the air's
// transmittance to it; the sun's disk. CPU twin: physics/atmosphere_sky.h
// marched_sky_radiance — change both together.
#ifndef VOLGRAPH_ATMOSPHERE_SKY_MARCH_GLSL
#define VOLGRAPH_ATMOSPHERE_SKY_MARCH_GLSL

#include "atmosphere_sky.glsl"
#include "atmosphere_sky_lookup.glsl"

struct SkyViewOptions {
  SkySampling sampling;
  bool sun_disk, limb_darkening, ground;
  float angular_radius;  // the sun's (rad)
};

// Ψ_ms(r, mu_s) from its LUT, 0 for single scattering alone.
vec3 multiscattering_at(AtmosphereParameters a, texture2D multiscattering_lut, sampler linear, float r, float mu_s, bool on) {
  if (!on) return vec3(0.0);
  const ivec2 size = textureSize(sampler2D(multiscattering_lut, linear), 0);
  return texture(sampler2D(multiscattering_lut, linear), multiscattering_lut_uv(a, r, mu_s, size)).rgb;
}

// `f.r` is the camera's radius as it is (not clamped to the top).
vec3 marched_sky_radiance(AtmosphereParameters a, texture2D transmittance_lut, sampler nearest, texture2D multiscattering_lut,
                          sampler linear, SkyFrame f, vec3 direction, SkyViewOptions o) {
  const vec3 disk = o.sun_disk ? sun_disk_radiance(a, transmittance_lut, nearest, f, direction, o.angular_radius, o.limb_darkening) : vec3(0.0);
  float r = max(f.r, atmosphere_bottom(a));
  float mu = clamp(dot(direction, f.up), -1.0, 1.0);
  const float nu = clamp(dot(direction, f.toward_sun), -1.0, 1.0);
  float mu_s = f.mu_s;
  if (r > atmosphere_top(a)) {  // Hillaire 2020, MoveToTopAtmosphere
    const float entry = enter_atmosphere(a, r, mu);
    if (entry < 0.0) return disk;
    mu_s = mu_s_at(r, mu, mu_s, nu, entry);
    mu = mu_at(r, mu, entry);
    r = atmosphere_top(a);
  }
  const float len = distance_to_boundary(a, r, mu);
  const ScatteringAlong along =
      scattering_along(a, transmittance_lut, nearest, multiscattering_lut, linear, r, mu, mu_s, nu, len, o.sampling);
  vec3 radiance = along.radiance + disk;
  if (!o.ground || !ray_hits_ground(a, r, mu)) return radiance;
  const float ground_mu_s = mu_s_at(r, mu, mu_s, nu, len);
  const vec3 psi = multiscattering_at(a, multiscattering_lut, linear, atmosphere_bottom(a), ground_mu_s, o.sampling.multiscattering);
  return radiance + along.transmittance * ground_radiance(a, transmittance_lut, nearest, ground_mu_s, psi);
}

// The ground seen from inside the atmosphere beside a sky-view LUT (which holds the air's
// in-scattering alone): the ground's radiance times the transmittance to it from the
// transmittance LUT; 0 where the ray misses the ground. physics::seen_ground_radiance.
vec3 seen_ground_radiance(AtmosphereParameters a, texture2D transmittance_lut, sampler nearest, texture2D multiscattering_lut,
                          sampler linear, SkyFrame f, vec3 direction, bool multiscattering) {
  const float r = max(f.r, atmosphere_bottom(a)), mu = clamp(dot(direction, f.up), -1.0, 1.0);
  if (!ray_hits_ground(a, r, mu)) return vec3(0.0);
  const float d = distance_to_ground(a, r, mu);
  const float ground_mu_s = mu_s_at(r, mu, f.mu_s, clamp(dot(direction, f.toward_sun), -1.0, 1.0), d);
  const vec3 psi = multiscattering_at(a, multiscattering_lut, linear, atmosphere_bottom(a), ground_mu_s, multiscattering);
  return transmittance_to_ground_lookup(a, transmittance_lut, nearest, r, mu, d) *
         ground_radiance(a, transmittance_lut, nearest, ground_mu_s, psi);
}

#endif
