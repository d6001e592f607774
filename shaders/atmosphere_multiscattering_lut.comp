#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_multiscattering_lut: per texel, the (r, mu_s) it holds (Hillaire 2020's
// linear mapping, include/atmosphere_lut.glsl) and Ψ_ms there
// (include/atmosphere_multiscattering.glsl).
#include "include/atmosphere_multiscattering.glsl"
#include "include/multiscattering_lut_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform MultiscatteringLutParamsBlock { MultiscatteringLutParams params; };
layout(set = 0, binding = 2) uniform texture2D transmittance;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4, rgba16f) uniform writeonly image2D multiscattering_lut;

void main() {
  const ivec2 size = imageSize(multiscattering_lut);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;
  const vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  const vec2 r_mu_s = multiscattering_lut_r_mu_s(atmosphere.a, uv, size);
  const vec3 psi = multiscattering(atmosphere.a, transmittance, nearest, r_mu_s.x, r_mu_s.y, params.sampling.x, params.sampling.y);
  imageStore(multiscattering_lut, texel, vec4(psi, 1.0));
}
