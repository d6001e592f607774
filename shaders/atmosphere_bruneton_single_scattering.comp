#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_bruneton_tables/single_scattering: per scattering texel (r, mu, mu_s, nu), the
// Rayleigh and Mie single scattering for a sun of unit irradiance without the phases
// (Bruneton 2017, ComputeSingleScatteringTexture: 50 trapezoids to the nearest boundary)
// into delta_rayleigh and delta_mie, the scattering sum started as Rayleigh (rgb), and the
// single Mie table (rgb: Bruneton 2017 without COMBINED_SCATTERING_TEXTURES).
#include "include/atmosphere_bruneton.glsl"
#include "include/bruneton_table_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform BrunetonTableParamsBlock { BrunetonTableParams params; };
layout(set = 0, binding = 2) uniform texture2D transmittance;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image3D delta_rayleigh;
layout(set = 0, binding = 5, rgba32f) uniform writeonly image3D delta_mie;
layout(set = 0, binding = 6, rgba32f) uniform writeonly image3D scattering_sum;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image3D single_mie_scattering;


void main() {
  const int SAMPLES = max(params.order.z, 1);  // trapezoids along the ray (Bruneton 2017's SAMPLE_COUNT: 50)
  const ivec3 texel = ivec3(gl_GlobalInvocationID.xyz);
  if (any(greaterThanEqual(texel, imageSize(delta_rayleigh)))) return;
  const AtmosphereParameters a = atmosphere.a;
  const BrunetonParams p = bruneton_scattering_texel_params(a, texel, params.size);
  // Bruneton 2017, ComputeSingleScattering / ComputeSingleScatteringIntegrand.
  const float dx = bruneton_nearest_boundary(a, p.r, p.mu, p.ray_hits_ground) / float(SAMPLES);
  vec3 rayleigh = vec3(0.0), mie = vec3(0.0);
  for (int i = 0; i <= SAMPLES; ++i) {
    const float d = float(i) * dx;
    const float r_d = bruneton_clamp_radius(a, radius_at(p.r, p.mu, d));
    const float mu_s_d = clamp((p.r * p.mu_s + d * p.nu) / r_d, -1.0, 1.0);
    const float altitude = max(altitude_at(a, p.r, p.mu, d), 0.0);
    const vec3 t = bruneton_transmittance(a, transmittance, nearest, p.r, p.mu, d, p.ray_hits_ground) *
                   sun_transmittance_lookup(a, transmittance, nearest, r_d, mu_s_d);
    const float weight = (i == 0 || i == SAMPLES) ? 0.5 : 1.0;
    rayleigh += t * (weight * profile_density(a.rayleigh_density, altitude));
    mie += t * (weight * profile_density(a.mie_density, altitude));
  }
  rayleigh *= dx * a.rayleigh_scattering.rgb;
  mie *= dx * a.mie_scattering.rgb;
  imageStore(delta_rayleigh, texel, vec4(rayleigh, 1.0));
  imageStore(delta_mie, texel, vec4(mie, 1.0));
  imageStore(scattering_sum, texel, vec4(rayleigh, 0.0));
  imageStore(single_mie_scattering, texel, vec4(mie, 0.0));
}
