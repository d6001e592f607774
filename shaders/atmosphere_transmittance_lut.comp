#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_transmittance_lut: per texel, the (r, mu) it holds in Bruneton 2017's
// parametrisation (include/atmosphere_lut.glsl) and the transmittance along that ray to the
// top of the atmosphere (include/atmosphere.glsl: Gauss–Legendre panels).
#include "include/atmosphere.glsl"
#include "include/atmosphere_lut.glsl"
#include "include/transmittance_lut_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform TransmittanceLutParamsBlock { TransmittanceLutParams params; };
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D transmittance;

void main() {
  const ivec2 size = imageSize(transmittance);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;
  const vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  const vec2 r_mu = transmittance_lut_r_mu(atmosphere.a, uv, size);
  const vec3 t = transmittance_to_top(atmosphere.a, r_mu.x, r_mu.y, params.panels.x);
  imageStore(transmittance, texel, vec4(t, 1.0));
}
