#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_bruneton_tables/multiple_<n>: per scattering texel, the radiance of order n
// toward the texel's point from its ray (Bruneton 2017, ComputeMultipleScatteringTexture:
// the density of order n times the transmittance, 50 trapezoids to the nearest boundary)
// into delta_multiple, and the scattering sum's next value: the previous one plus it over
// the Rayleigh phase (the table's rgb is read with p_R(nu) at lookup).
#include "include/atmosphere_bruneton.glsl"
#include "include/bruneton_table_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform BrunetonTableParamsBlock { BrunetonTableParams params; };
layout(set = 0, binding = 2) uniform texture2D transmittance;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4) uniform texture3D density;
layout(set = 0, binding = 5) uniform texture3D scattering_previous;
layout(set = 0, binding = 6, rgba32f) uniform writeonly image3D delta_multiple;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image3D scattering_next;


void main() {
  const int SAMPLES = max(params.order.z, 1);  // trapezoids along the ray (Bruneton 2017's SAMPLE_COUNT: 50)
  const ivec3 texel = ivec3(gl_GlobalInvocationID.xyz);
  if (any(greaterThanEqual(texel, imageSize(delta_multiple)))) return;
  const AtmosphereParameters a = atmosphere.a;
  const vec4 previous = texelFetch(sampler3D(scattering_previous, nearest), texel, 0);
  if (params.order.y == 0) {
    imageStore(delta_multiple, texel, vec4(0.0));
    imageStore(scattering_next, texel, previous);
    return;
  }
  const BrunetonParams p = bruneton_scattering_texel_params(a, texel, params.size);
  // Bruneton 2017, ComputeMultipleScattering.
  const float dx = bruneton_nearest_boundary(a, p.r, p.mu, p.ray_hits_ground) / float(SAMPLES);
  vec3 sum = vec3(0.0);
  for (int i = 0; i <= SAMPLES; ++i) {
    const float d = float(i) * dx;
    const float r_i = bruneton_clamp_radius(a, radius_at(p.r, p.mu, d));
    const float mu_i = clamp((p.r * p.mu + d) / r_i, -1.0, 1.0);
    const float mu_s_i = clamp((p.r * p.mu_s + d * p.nu) / r_i, -1.0, 1.0);
    const vec3 j = bruneton_scattering(a, density, nearest, params.size, r_i, mu_i, mu_s_i, p.nu, p.ray_hits_ground).rgb;
    const vec3 t = bruneton_transmittance(a, transmittance, nearest, p.r, p.mu, d, p.ray_hits_ground);
    const float weight = (i == 0 || i == SAMPLES) ? 0.5 : 1.0;
    sum += j * t * (dx * weight);
  }
  imageStore(delta_multiple, texel, vec4(sum, 1.0));
  imageStore(scattering_next, texel, previous + vec4(sum / phase_rayleigh(p.nu), 0.0));
}
