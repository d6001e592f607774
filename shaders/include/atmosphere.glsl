// A planet's atmosphere (Bruneton 2017's model) in float: densities, coefficients, the
// stable ray–sphere distances, optical depth by a fixed-count quadrature, transmittance and
// the sun's. CPU twin: physics/atmosphere.h — change both together; the formulas, their
// sources and their precision notes are documented there. A point is (r, mu): its distance
// r from the planet's centre (m) and the cosine of its ray's zenith angle.
#ifndef VOLGRAPH_ATMOSPHERE_GLSL
#define VOLGRAPH_ATMOSPHERE_GLSL

#include "phase.glsl"

const float MIE_PHASE_HENYEY_GREENSTEIN = 0.0;
const float MIE_PHASE_CORNETTE_SHANKS = 1.0;

#include "atmosphere_parameters.h"  // AtmosphereLayer, AtmosphereProfile, AtmosphereParameters (physics::pack_atmosphere fills them)

float atmosphere_bottom(AtmosphereParameters a) { return a.radii.x; }
float atmosphere_top(AtmosphereParameters a) { return a.radii.y; }

// Bruneton 2017, GetLayerDensity / GetProfileDensity: clamped to [0, 1].
float layer_density(AtmosphereLayer layer, float altitude) {
  const vec4 t = layer.terms;
  return clamp(t.x * exp(t.y * altitude) + t.z * altitude + t.w, 0.0, 1.0);
}

float profile_density(AtmosphereProfile profile, float altitude) {
  return altitude < profile.width.x ? layer_density(profile.lower, altitude) : layer_density(profile.upper, altitude);
}

vec3 rayleigh_scattering_at(AtmosphereParameters a, float altitude) {
  return a.rayleigh_scattering.xyz * profile_density(a.rayleigh_density, altitude);
}
vec3 mie_scattering_at(AtmosphereParameters a, float altitude) { return a.mie_scattering.xyz * profile_density(a.mie_density, altitude); }
vec3 mie_extinction_at(AtmosphereParameters a, float altitude) { return a.mie_extinction.xyz * profile_density(a.mie_density, altitude); }
vec3 absorption_at(AtmosphereParameters a, float altitude) {
  return a.absorption_extinction.xyz * profile_density(a.absorption_density, altitude);
}
// Rayleigh + Mie extinction + absorption (Bruneton 2017, ComputeTransmittanceToTopAtmosphereBoundary).
vec3 extinction_at(AtmosphereParameters a, float altitude) {
  return rayleigh_scattering_at(a, altitude) + mie_extinction_at(a, altitude) + absorption_at(a, altitude);
}

// d² + 2bd + c = 0 with b = r·mu, c from the altitude: c = h(2·radius + h), h = r − radius.
float sphere_constant_term(float r, float radius) {
  const float h = r - radius;
  return h * (2.0 * radius + h);
}

// The nearer root −b − √Δ, as c / (√Δ − b) when b < 0 (Numerical Recipes §5.6).
float sphere_near_root(float b, float c) {
  const float sqrt_discriminant = sqrt(max(b * b - c, 0.0));
  if (b < 0.0) return c / (sqrt_discriminant - b);
  return -b - sqrt_discriminant;
}

// The farther root −b + √Δ, as −c / (b + √Δ) when b > 0.
float sphere_far_root(float b, float c) {
  const float sqrt_discriminant = sqrt(max(b * b - c, 0.0));
  if (b > 0.0) return -c / max(b + sqrt_discriminant, 1.17549435e-38);
  return sqrt_discriminant - b;
}

// From inside: where the ray leaves the sphere; from outside or on it: where it enters,
// −1 when it misses or heads away.
float distance_to_sphere(float r, float mu, float radius) {
  const float b = r * mu, c = sphere_constant_term(r, radius);
  if (c < 0.0) return max(sphere_far_root(b, c), 0.0);
  if (b >= 0.0 || b * b - c < 0.0) return -1.0;
  return max(sphere_near_root(b, c), 0.0);
}

// Bruneton 2017, DistanceToTopAtmosphereBoundary (the ground ignored).
float distance_to_top(AtmosphereParameters a, float r, float mu) {
  return max(sphere_far_root(r * mu, sphere_constant_term(r, atmosphere_top(a))), 0.0);
}

// Bruneton 2017, RayIntersectsGround.
bool ray_hits_ground(AtmosphereParameters a, float r, float mu) {
  const float b = r * mu;
  return mu < 0.0 && b * b - sphere_constant_term(r, atmosphere_bottom(a)) >= 0.0;
}

// Bruneton 2017, DistanceToBottomAtmosphereBoundary; −1 when the ray misses the ground.
float distance_to_ground(AtmosphereParameters a, float r, float mu) {
  if (!ray_hits_ground(a, r, mu)) return -1.0;
  return max(sphere_near_root(r * mu, sphere_constant_term(r, atmosphere_bottom(a))), 0.0);
}

float distance_to_boundary(AtmosphereParameters a, float r, float mu) {
  return ray_hits_ground(a, r, mu) ? distance_to_ground(a, r, mu) : distance_to_top(a, r, mu);
}

// A camera above the atmosphere: the distance to the top sphere (0 inside), −1 when the
// ray misses the atmosphere (Hillaire 2020's MoveToTopAtmosphere).
float enter_atmosphere(AtmosphereParameters a, float r, float mu) {
  if (r <= atmosphere_top(a)) return 0.0;
  return distance_to_sphere(r, mu, atmosphere_top(a));
}

// The law of cosines (Bruneton 2017, ComputeSingleScatteringIntegrand's r_d, mu_d).
float radius_at(float r, float mu, float d) {
  const float growth = d * (d + 2.0 * r * mu);
  const float r_d = sqrt(max(r * r + growth, 0.0));
  if (r + r_d <= 0.0) return 0.0;
  return max(r + growth / (r + r_d), 0.0);
}

float mu_at(float r, float mu, float d) {
  const float r_d = radius_at(r, mu, d);
  if (r_d <= 0.0) return mu;
  return clamp((r * mu + d) / r_d, -1.0, 1.0);
}

// r_d − bottom as (r − bottom) + d(d + 2r·mu) / (r + r_d): keeps its relative precision.
// The sun's zenith cosine d along the ray (Bruneton 2017: (r mu_s + d nu) / r_d).
float mu_s_at(float r, float mu, float mu_s, float nu, float d) {
  const float rd = radius_at(r, mu, d);
  return rd > 0.0 ? clamp((r * mu_s + d * nu) / rd, -1.0, 1.0) : mu_s;
}

float altitude_at(AtmosphereParameters a, float r, float mu, float d) {
  const float growth = d * (d + 2.0 * r * mu);
  const float r_d = sqrt(max(r * r + growth, 0.0));
  if (r + r_d <= 0.0) return -atmosphere_bottom(a);
  return (r - atmosphere_bottom(a)) + growth / (r + r_d);
}

// −√(1 − (bottom / r)²), from the altitude.
float mu_horizon(AtmosphereParameters a, float r) {
  if (r <= 0.0) return 0.0;
  return -sqrt(max(sphere_constant_term(r, atmosphere_bottom(a)), 0.0)) / r;
}

// ∫ extinction over [0, length] of the ray: `panels` equal panels of 4-point
// Gauss–Legendre (Abramowitz & Stegun, Table 25.4); physics::optical_depth_fixed.
vec3 optical_depth(AtmosphereParameters a, float r, float mu, float len, int panels) {
  vec3 total = vec3(0.0);
  if (!(len > 0.0) || panels < 1) return total;
  const vec2 nodes = vec2(0.3399810435848563, 0.8611363115940526);
  const vec2 weights = vec2(0.6521451548625461, 0.3478548451374538);
  const float half_width = 0.5 * len / float(panels);
  for (int p = 0; p < panels; ++p) {
    const float centre = float(2 * p + 1) * half_width;
    for (int i = 0; i < 2; ++i) {
      const vec3 sides = extinction_at(a, altitude_at(a, r, mu, centre - half_width * nodes[i])) +
                         extinction_at(a, altitude_at(a, r, mu, centre + half_width * nodes[i]));
      total += sides * (weights[i] * half_width);
    }
  }
  return total;
}

// e^(−optical depth to the top), the ground ignored; below the horizon the horizon's value
// (Bruneton 2017's transmittance texture, ComputeTransmittanceToTopAtmosphereBoundary).
vec3 transmittance_to_top(AtmosphereParameters a, float r, float mu, int panels) {
  mu = max(mu, mu_horizon(a, r));
  return exp(-optical_depth(a, r, mu, distance_to_top(a, r, mu), panels));
}

// e^(−optical depth to the ground or the top).
vec3 transmittance_to_boundary(AtmosphereParameters a, float r, float mu, int panels) {
  return exp(-optical_depth(a, r, mu, distance_to_boundary(a, r, mu), panels));
}

// Bruneton 2017, GetTransmittanceToSun: the fraction of the sun's disk above the horizon.
float sun_visible_fraction(AtmosphereParameters a, float r, float mu_s) {
  const float sin_theta_h = min(atmosphere_bottom(a) / max(r, atmosphere_bottom(a)), 1.0);
  const float half_width = sin_theta_h * a.radii.z;
  const float x = mu_s - mu_horizon(a, r);
  if (half_width <= 0.0) return x >= 0.0 ? 1.0 : 0.0;
  const float t = clamp((x + half_width) / (2.0 * half_width), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

vec3 sun_transmittance(AtmosphereParameters a, float r, float mu_s, int panels) {
  const float fraction = sun_visible_fraction(a, r, mu_s);
  if (fraction <= 0.0) return vec3(0.0);
  return transmittance_to_top(a, r, mu_s, panels) * fraction;
}

float mie_phase(AtmosphereParameters a, float cos_theta) {
  if (a.mie_scattering.w == MIE_PHASE_HENYEY_GREENSTEIN) return phase_hg(a.radii.w, cos_theta);
  return phase_cornette_shanks(a.radii.w, cos_theta);
}

#endif
