#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_bruneton_tables/indirect_irradiance_<n>: per irradiance texel, the sky's
// irradiance of order n − 1 on a horizontal surface (Bruneton 2017,
// ComputeIndirectIrradiance: 16 × 64 directions of the upper hemisphere) into
// delta_irradiance, and the irradiance sum's next value (the previous one plus it).
#include "include/atmosphere_bruneton.glsl"
#include "include/bruneton_table_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform BrunetonTableParamsBlock { BrunetonTableParams params; };
layout(set = 0, binding = 2) uniform texture3D delta_rayleigh;
layout(set = 0, binding = 3) uniform texture3D delta_mie;
layout(set = 0, binding = 4) uniform texture3D delta_multiple;
layout(set = 0, binding = 5) uniform sampler nearest;
layout(set = 0, binding = 6) uniform texture2D irradiance_previous;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D delta_irradiance;
layout(set = 0, binding = 8, rgba32f) uniform writeonly image2D irradiance_next;

const int SAMPLES = 32;  // Bruneton 2017, ComputeIndirectIrradiance's SAMPLE_COUNT

// Bruneton 2017, GetScattering(…, scattering_order) for rays that miss the ground.
vec3 incident_order(AtmosphereParameters a, float r, float mu, float mu_s, float nu, int order) {
  if (order == 1) {
    const vec3 rayleigh = bruneton_scattering(a, delta_rayleigh, nearest, params.size, r, mu, mu_s, nu, false).rgb;
    const vec3 mie = bruneton_scattering(a, delta_mie, nearest, params.size, r, mu, mu_s, nu, false).rgb;
    return rayleigh * phase_rayleigh(nu) + mie * mie_phase(a, nu);
  }
  return bruneton_scattering(a, delta_multiple, nearest, params.size, r, mu, mu_s, nu, false).rgb;
}

void main() {
  const ivec2 size = imageSize(delta_irradiance);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;
  const vec3 previous = texelFetch(sampler2D(irradiance_previous, nearest), texel, 0).rgb;
  if (params.order.y == 0) {
    imageStore(delta_irradiance, texel, vec4(0.0));
    imageStore(irradiance_next, texel, vec4(previous, 1.0));
    return;
  }
  const AtmosphereParameters a = atmosphere.a;
  const vec2 r_mu_s = bruneton_irradiance_r_mu_s(a, (vec2(texel) + 0.5) / vec2(size), size);
  const float r = r_mu_s.x, mu_s = r_mu_s.y;
  const int order = params.order.x - 1;
  const float dphi = ATMOSPHERE_PI / float(SAMPLES), dtheta = ATMOSPHERE_PI / float(SAMPLES);
  const vec3 omega_s = vec3(sqrt(max(1.0 - mu_s * mu_s, 0.0)), 0.0, mu_s);
  vec3 e = vec3(0.0);
  for (int j = 0; j < SAMPLES / 2; ++j) {
    const float theta = (float(j) + 0.5) * dtheta;
    for (int i = 0; i < 2 * SAMPLES; ++i) {
      const float phi = (float(i) + 0.5) * dphi;
      const vec3 omega = vec3(cos(phi) * sin(theta), sin(phi) * sin(theta), cos(theta));
      const float domega = dtheta * dphi * sin(theta);
      e += incident_order(a, r, omega.z, mu_s, dot(omega, omega_s), order) * omega.z * domega;
    }
  }
  imageStore(delta_irradiance, texel, vec4(e, 1.0));
  imageStore(irradiance_next, texel, vec4(previous + e, 1.0));
}
