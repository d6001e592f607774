#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_bruneton_tables/density_<n>: per scattering texel, the light scattered toward
// −omega at the texel's point after n − 1 bounces, per metre (Bruneton 2017,
// ComputeScatteringDensity: 16 × 32 incident directions; the (n−1)-th order from the delta
// tables — single Rayleigh and Mie with their phases for n = 2, delta_multiple above — and
// the ground's light of order n − 2 from delta_irradiance through its albedo).
#include "include/atmosphere_bruneton.glsl"
#include "include/bruneton_table_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform BrunetonTableParamsBlock { BrunetonTableParams params; };
layout(set = 0, binding = 2) uniform texture2D transmittance;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4) uniform texture3D delta_rayleigh;
layout(set = 0, binding = 5) uniform texture3D delta_mie;
layout(set = 0, binding = 6) uniform texture3D delta_multiple;
layout(set = 0, binding = 7) uniform texture2D delta_irradiance;
layout(set = 0, binding = 8, rgba32f) uniform writeonly image3D density;

const int SAMPLES = 16;  // Bruneton 2017, ComputeScatteringDensity's SAMPLE_COUNT

// Bruneton 2017, GetScattering(…, scattering_order): order 1 with its phases, else the delta table.
vec3 incident_order(AtmosphereParameters a, float r, float mu, float mu_s, float nu, bool hits_ground, int order) {
  if (order == 1) {
    const vec3 rayleigh = bruneton_scattering(a, delta_rayleigh, nearest, params.size, r, mu, mu_s, nu, hits_ground).rgb;
    const vec3 mie = bruneton_scattering(a, delta_mie, nearest, params.size, r, mu, mu_s, nu, hits_ground).rgb;
    return rayleigh * phase_rayleigh(nu) + mie * mie_phase(a, nu);
  }
  return bruneton_scattering(a, delta_multiple, nearest, params.size, r, mu, mu_s, nu, hits_ground).rgb;
}

void main() {
  const ivec3 texel = ivec3(gl_GlobalInvocationID.xyz);
  if (any(greaterThanEqual(texel, imageSize(density)))) return;
  const AtmosphereParameters a = atmosphere.a;
  const BrunetonParams p = bruneton_scattering_texel_params(a, texel, params.size);
  const int order = params.order.x;
  // The zenith, the view omega and the sun omega_s with cosines mu, mu_s and nu.
  const vec3 zenith = vec3(0.0, 0.0, 1.0);
  const vec3 omega = vec3(sqrt(max(1.0 - p.mu * p.mu, 0.0)), 0.0, p.mu);
  const float sun_x = omega.x == 0.0 ? 0.0 : (p.nu - p.mu * p.mu_s) / omega.x;
  const vec3 omega_s = vec3(sun_x, sqrt(max(1.0 - sun_x * sun_x - p.mu_s * p.mu_s, 0.0)), p.mu_s);
  const float dphi = ATMOSPHERE_PI / float(SAMPLES), dtheta = ATMOSPHERE_PI / float(SAMPLES);
  const float altitude = p.r - atmosphere_bottom(a);
  const vec3 rayleigh_here = a.rayleigh_scattering.rgb * profile_density(a.rayleigh_density, altitude);
  const vec3 mie_here = a.mie_scattering.rgb * profile_density(a.mie_density, altitude);
  vec3 sum = vec3(0.0);
  for (int l = 0; l < SAMPLES; ++l) {
    const float theta = (float(l) + 0.5) * dtheta;
    const float cos_theta = cos(theta), sin_theta = sin(theta);
    const bool hits_ground = ray_hits_ground(a, p.r, cos_theta);
    // The ground's distance and transmittance depend on theta alone.
    float ground_distance = 0.0;
    vec3 ground_transmittance = vec3(0.0);
    if (hits_ground) {
      ground_distance = bruneton_ground_distance(a, p.r, cos_theta);
      ground_transmittance = bruneton_transmittance(a, transmittance, nearest, p.r, cos_theta, ground_distance, true) * a.ground_albedo.rgb;
    }
    for (int m = 0; m < 2 * SAMPLES; ++m) {
      const float phi = (float(m) + 0.5) * dphi;
      const vec3 omega_i = vec3(cos(phi) * sin_theta, sin(phi) * sin_theta, cos_theta);
      const float domega = dtheta * dphi * sin_theta;
      vec3 incident = incident_order(a, p.r, omega_i.z, p.mu_s, dot(omega_s, omega_i), hits_ground, order - 1);
      if (hits_ground) {
        // The light of order n − 1 whose last bounce is the Lambertian ground.
        const vec3 normal = normalize(zenith * p.r + omega_i * ground_distance);
        const vec3 e = bruneton_irradiance(a, delta_irradiance, nearest, atmosphere_bottom(a), dot(normal, omega_s));
        incident += ground_transmittance * e * (1.0 / ATMOSPHERE_PI);
      }
      const float nu2 = dot(omega, omega_i);
      sum += incident * (rayleigh_here * phase_rayleigh(nu2) + mie_here * mie_phase(a, nu2)) * domega;
    }
  }
  imageStore(density, texel, vec4(sum, 1.0));
}
