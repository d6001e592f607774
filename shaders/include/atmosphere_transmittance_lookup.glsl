// Reading the transmittance LUT (atmosphere_transmittance_lut, rgba32f: fetched, since
// WebGPU filters no 32-bit float texture): the bilinear blend of the four texels around
// (r, mu)'s texture coordinate (include/atmosphere_lut.glsl), and the sun's transmittance
// through it (Bruneton 2017, GetTransmittanceToSun).
#ifndef VOLGRAPH_ATMOSPHERE_TRANSMITTANCE_LOOKUP_GLSL
#define VOLGRAPH_ATMOSPHERE_TRANSMITTANCE_LOOKUP_GLSL

#include "atmosphere.glsl"
#include "atmosphere_lut.glsl"

vec3 transmittance_lut_texel(texture2D lut, sampler nearest, ivec2 texel, ivec2 size) {
  return texelFetch(sampler2D(lut, nearest), clamp(texel, ivec2(0), size - 1), 0).rgb;
}

// The transmittance to the top from (r, mu), mu at or above the horizon (below it: the
// horizon's, as the table holds no ray that hits the ground).
vec3 transmittance_lookup(AtmosphereParameters a, texture2D lut, sampler nearest, float r, float mu) {
  const ivec2 size = textureSize(sampler2D(lut, nearest), 0);
  const vec2 uv = transmittance_lut_uv(a, r, max(mu, mu_horizon(a, r)), size);
  const vec2 x = uv * vec2(size) - 0.5;
  const ivec2 base = ivec2(floor(x));
  const vec2 f = x - vec2(base);
  const vec3 bottom = mix(transmittance_lut_texel(lut, nearest, base, size), transmittance_lut_texel(lut, nearest, base + ivec2(1, 0), size), f.x);
  const vec3 top = mix(transmittance_lut_texel(lut, nearest, base + ivec2(0, 1), size), transmittance_lut_texel(lut, nearest, base + ivec2(1, 1), size), f.x);
  return mix(bottom, top, f.y);
}

vec3 sun_transmittance_lookup(AtmosphereParameters a, texture2D lut, sampler nearest, float r, float mu_s) {
  const float fraction = sun_visible_fraction(a, r, mu_s);
  if (fraction <= 0.0) return vec3(0.0);
  return transmittance_lookup(a, lut, nearest, r, mu_s) * fraction;
}

#endif
