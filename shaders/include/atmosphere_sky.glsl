// The light the atmosphere scatters toward a viewer along a ray, the sun's transmittance
// and Ψ_ms read from their LUTs (Hillaire 2020 §5.3). CPU twin: physics/atmosphere_sky.h
// (the integral, its sampling and its sources are documented there) — change both together.
#ifndef VOLGRAPH_ATMOSPHERE_SKY_GLSL
#define VOLGRAPH_ATMOSPHERE_SKY_GLSL

#include "atmosphere_transmittance_lookup.glsl"

struct SkySampling {
  float min_samples, max_samples, full_samples_length;  // Hillaire 2020: 4, 14, 100 km
  float sample_offset;                                  // within each step (Hillaire 2020: 0.3)
  bool multiscattering;                                 // false: single scattering alone
  vec3 world_origin, world_direction;                   // the ray in the scene's world (m): for the sun-visibility hook
};

// The sun-visibility hook: a shader that shadows the air's sunlight (the clouds' shadow)
// defines ATMOSPHERE_SUN_VISIBILITY and, after including this file, the function below: the
// fraction of the sun that reaches world point p. It dims the single-scattering source
// only (Ψ_ms, the light the air has already scattered, stays: Hillaire 2020's volumetric
// shadows in the aerial-perspective volume do the same). Without it the visibility is 1.
#ifdef ATMOSPHERE_SUN_VISIBILITY
float atmosphere_sun_visibility(vec3 p);
#endif
float sun_visibility_along(SkySampling sampling, float t) {
#ifdef ATMOSPHERE_SUN_VISIBILITY
  return atmosphere_sun_visibility(sampling.world_origin + t * sampling.world_direction);
#else
  return 1.0;
#endif
}

float view_sun_cosine(float mu, float cos_azimuth, float mu_s) {
  return clamp(sqrt(max(0.0, 1.0 - mu * mu)) * sqrt(max(0.0, 1.0 - mu_s * mu_s)) * cos_azimuth + mu * mu_s, -1.0, 1.0);
}

struct ScatteringAlong {
  vec3 radiance;
  vec3 transmittance;
};

// The light scattered toward the viewer over the first `len` m of the ray (r, mu), and the
// ray's transmittance over them (aerial perspective; the whole ray: the sky).
ScatteringAlong scattering_along(AtmosphereParameters a, texture2D transmittance_lut, sampler nearest, texture2D multiscattering_lut,
                                 sampler linear, float r, float mu, float mu_s, float nu, float len, SkySampling sampling) {
  ScatteringAlong along = ScatteringAlong(vec3(0.0), vec3(1.0));
  if (!(len > 0.0)) return along;
  const float count = mix(sampling.min_samples, sampling.max_samples, clamp(len / sampling.full_samples_length, 0.0, 1.0));
  const float whole = max(1.0, floor(count));
  const float covered = len * whole / count;
  const float rayleigh_phase = phase_rayleigh(nu), mie = mie_phase(a, nu);
  const ivec2 ms_size = textureSize(sampler2D(multiscattering_lut, linear), 0);
  const int samples = int(whole);
  for (int s = 0; s < samples; ++s) {
    const float t0 = covered * (float(s) / whole) * (float(s) / whole);
    const float t1 = s + 1 == samples ? len : covered * (float(s + 1) / whole) * (float(s + 1) / whole);
    const float dt = t1 - t0;
    const float t = t0 + sampling.sample_offset * dt;
    const float rd = radius_at(r, mu, t), altitude = altitude_at(a, r, mu, t);
    const float sun_mu = mu_s_at(r, mu, mu_s, nu, t);
    const vec3 rayleigh = rayleigh_scattering_at(a, altitude), mie_s = mie_scattering_at(a, altitude);
    const vec3 extinction = extinction_at(a, altitude);
    const vec3 sun = sun_transmittance_lookup(a, transmittance_lut, nearest, rd, sun_mu) * sun_visibility_along(sampling, t);
    vec3 psi = vec3(0.0);
    if (sampling.multiscattering) {
      psi = textureLod(sampler2D(multiscattering_lut, linear), multiscattering_lut_uv(a, rd, sun_mu, ms_size), 0.0).rgb;
    }
    const vec3 source = (rayleigh * rayleigh_phase + mie_s * mie) * sun + (rayleigh + mie_s) * psi;
    const vec3 step_transmittance = exp(-extinction * dt);
    along.radiance += along.transmittance * mix(source * dt, source * (1.0 - step_transmittance) / max(extinction, vec3(1e-30)),
                                                greaterThan(extinction, vec3(0.0)));
    along.transmittance *= step_transmittance;
  }
  return along;
}

vec3 sky_scattering(AtmosphereParameters a, texture2D transmittance_lut, sampler nearest, texture2D multiscattering_lut,
                    sampler linear, float r, float mu, float mu_s, float nu, SkySampling sampling) {
  return scattering_along(a, transmittance_lut, nearest, multiscattering_lut, linear, r, mu, mu_s, nu, distance_to_boundary(a, r, mu),
                          sampling).radiance;
}

#endif
