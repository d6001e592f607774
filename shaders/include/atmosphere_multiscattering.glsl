// Hillaire 2020 §5.5: Ψ_ms(r, mu_s), the isotropic contribution of every scattering order
// past the first for a sun of unit illuminance, the sun's transmittance read from the
// transmittance LUT. CPU twin: physics/atmosphere_multiscattering.h (the method, its
// equations and its sources are documented there) — change both together.
#ifndef VOLGRAPH_ATMOSPHERE_MULTISCATTERING_GLSL
#define VOLGRAPH_ATMOSPHERE_MULTISCATTERING_GLSL

#include "atmosphere_transmittance_lookup.glsl"

const float MULTISCATTERING_ISOTROPIC_PHASE = 1.0 / (4.0 * ATMOSPHERE_PI);

struct MultiscatteringTerms {
  vec3 second_order;  // L_2nd (eq. 5)
  vec3 transfer;      // f_ms (eq. 7)
};

// One ray's L_f and ∫σs T dt, marched from (r, mu) to its boundary in `steps` midpoint steps.
MultiscatteringTerms multiscattering_march(AtmosphereParameters a, texture2D lut, sampler nearest, float r, float mu, float mu_s,
                                           float nu, int steps) {
  MultiscatteringTerms terms = MultiscatteringTerms(vec3(0.0), vec3(0.0));
  const float len = distance_to_boundary(a, r, mu);
  const float dt = len / float(steps);
  vec3 throughput = vec3(1.0);
  for (int s = 0; s < steps; ++s) {
    const float d = (float(s) + 0.5) * dt;
    const float rd = radius_at(r, mu, d);
    const float altitude = altitude_at(a, r, mu, d);
    const vec3 scattering = rayleigh_scattering_at(a, altitude) + mie_scattering_at(a, altitude);
    const vec3 extinction = extinction_at(a, altitude);
    const vec3 sun = sun_transmittance_lookup(a, lut, nearest, rd, mu_s_at(r, mu, mu_s, nu, d));
    const vec3 step_transmittance = exp(-extinction * dt);
    // Hillaire 2020 eq. 6, energy-conserving: ∫ over the step of σs e^(−σt t).
    const vec3 scattered = mix(scattering * dt, scattering * (1.0 - step_transmittance) / max(extinction, vec3(1e-30)),
                               greaterThan(extinction, vec3(0.0)));
    terms.second_order += throughput * sun * MULTISCATTERING_ISOTROPIC_PHASE * scattered;
    terms.transfer += throughput * scattered;
    throughput *= step_transmittance;
  }
  if (!ray_hits_ground(a, r, mu)) return terms;
  const float ground_mu_s = mu_s_at(r, mu, mu_s, nu, len);
  const vec3 sun = sun_transmittance_lookup(a, lut, nearest, atmosphere_bottom(a), ground_mu_s);
  terms.second_order += throughput * sun * max(ground_mu_s, 0.0) * a.ground_albedo.rgb / ATMOSPHERE_PI;
  return terms;
}

// Ψ_ms = L_2nd / (1 − f_ms) over `n`² directions uniform on the sphere (eq. 9, 10).
vec3 multiscattering(AtmosphereParameters a, texture2D lut, sampler nearest, float r, float mu_s, int n, int steps) {
  const float weight = 4.0 * ATMOSPHERE_PI / float(n * n) * MULTISCATTERING_ISOTROPIC_PHASE;
  const float sun_x = sqrt(max(0.0, 1.0 - mu_s * mu_s));
  vec3 second_order = vec3(0.0), transfer = vec3(0.0);
  for (int i = 0; i < n; ++i) {
    const float theta = 2.0 * ATMOSPHERE_PI * (float(i) + 0.5) / float(n);
    for (int j = 0; j < n; ++j) {
      const float cos_phi = 1.0 - 2.0 * (float(j) + 0.5) / float(n);
      const float sin_phi = sqrt(max(0.0, 1.0 - cos_phi * cos_phi));
      const float nu = cos(theta) * sin_phi * sun_x + cos_phi * mu_s;
      const MultiscatteringTerms ray = multiscattering_march(a, lut, nearest, r, cos_phi, mu_s, nu, steps);
      second_order += ray.second_order * weight;
      transfer += ray.transfer * weight;
    }
  }
  return second_order / max(1.0 - transfer, vec3(1e-6));
}

#endif
