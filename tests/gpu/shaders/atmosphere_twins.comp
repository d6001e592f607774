#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates atmosphere.glsl and atmosphere_lut.glsl on a table of rays, for the test that
// holds them to their CPU twins physics/atmosphere.h and atmosphere_lut.h
// (tests/gpu/atmosphere_twins_test.cpp).
#include "include/atmosphere_lut.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters atmosphere; } params;

struct Case {
  vec4 ray;  // r, mu, d (a distance along the ray), mu_s
  vec4 lut;  // u, v (a texture coordinate), cos_azimuth, cos θ (the phase's)
};
layout(set = 0, binding = 1) readonly buffer Cases { Case cases[]; };
layout(set = 0, binding = 2) writeonly buffer Results { vec4 results[]; };  // ATMOSPHERE_TWIN_ROWS per case

const uint ATMOSPHERE_TWIN_ROWS = 9;
const int PANELS = 40;
const ivec2 TRANSMITTANCE_SIZE = ivec2(256, 64), MULTISCATTERING_SIZE = ivec2(32, 32), SKY_VIEW_SIZE = ivec2(192, 108);

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= cases.length()) return;
  const AtmosphereParameters a = params.atmosphere;
  const float r = cases[i].ray.x, mu = cases[i].ray.y, d = cases[i].ray.z, mu_s = cases[i].ray.w;
  const vec2 uv = cases[i].lut.xy;
  const float cos_azimuth = cases[i].lut.z, cos_theta = cases[i].lut.w;
  const uint o = ATMOSPHERE_TWIN_ROWS * i;
  results[o] = vec4(distance_to_top(a, r, mu), distance_to_ground(a, r, mu), distance_to_boundary(a, r, mu), enter_atmosphere(a, r, mu));
  results[o + 1] = vec4(radius_at(r, mu, d), mu_at(r, mu, d), altitude_at(a, r, mu, d), mu_horizon(a, r));
  const float r_in = min(r, atmosphere_top(a));  // the LUTs and the transmittance: inside the atmosphere
  results[o + 2] = vec4(transmittance_to_top(a, r_in, mu, PANELS), sun_visible_fraction(a, r_in, mu_s));
  results[o + 3] = vec4(sun_transmittance(a, r_in, mu_s, PANELS), mie_phase(a, cos_theta));
  results[o + 4] = vec4(extinction_at(a, r_in - atmosphere_bottom(a)), profile_density(a.absorption_density, r_in - atmosphere_bottom(a)));
  results[o + 5] = vec4(transmittance_lut_uv(a, r_in, max(mu, mu_horizon(a, r_in)), TRANSMITTANCE_SIZE), transmittance_lut_r_mu(a, uv, TRANSMITTANCE_SIZE));
  results[o + 6] = vec4(multiscattering_lut_uv(a, r_in, mu_s, MULTISCATTERING_SIZE), multiscattering_lut_r_mu_s(a, uv, MULTISCATTERING_SIZE));
  results[o + 7] = vec4(sky_view_lut_uv(a, r_in, vec2(mu, cos_azimuth), SKY_VIEW_SIZE), sky_view_lut_direction(a, r_in, uv, SKY_VIEW_SIZE));
  results[o + 8] = vec4(optical_depth(a, r_in, mu, distance_to_boundary(a, r_in, mu), PANELS), phase_cornette_shanks(0.8, cos_theta));
}
