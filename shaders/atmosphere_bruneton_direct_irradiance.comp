#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_bruneton_tables/direct_irradiance: per irradiance texel (r, mu_s), the sun's
// irradiance on a horizontal surface for a sun of unit irradiance (Bruneton 2017,
// ComputeDirectIrradianceTexture) into delta_irradiance, and the irradiance sum started at
// 0 (the table holds the sky's irradiance alone; the sun's is added at lookup).
#include "include/atmosphere_bruneton.glsl"
#include "include/bruneton_table_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform BrunetonTableParamsBlock { BrunetonTableParams params; };
layout(set = 0, binding = 2) uniform texture2D transmittance;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D delta_irradiance;
layout(set = 0, binding = 5, rgba32f) uniform writeonly image2D irradiance_sum;

void main() {
  const ivec2 size = imageSize(delta_irradiance);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;
  const vec2 r_mu_s = bruneton_irradiance_r_mu_s(atmosphere.a, (vec2(texel) + 0.5) / vec2(size), size);
  const AtmosphereParameters a = atmosphere.a;
  // Bruneton 2017, ComputeDirectIrradiance: the cosine averaged over the sun's visible disk.
  const float alpha = a.radii.z, mu_s = r_mu_s.y;
  const float cosine = mu_s < -alpha ? 0.0 : (mu_s > alpha ? mu_s : (mu_s + alpha) * (mu_s + alpha) / (4.0 * alpha));
  const vec3 e = transmittance_lookup(a, transmittance, nearest, r_mu_s.x, mu_s) * cosine;
  imageStore(delta_irradiance, texel, vec4(e, 1.0));
  imageStore(irradiance_sum, texel, vec4(0.0));
}
