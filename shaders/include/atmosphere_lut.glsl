// The atmosphere's LUT parametrisations in float: the transmittance texture (Bruneton
// 2017), the multiple-scattering LUT and the sky-view LUT (Hillaire 2020). CPU twin:
// physics/atmosphere_lut.h — change both together; the mappings and their sources are
// documented there. Sizes are passed as ivec2 (width, height).
#ifndef VOLGRAPH_ATMOSPHERE_LUT_GLSL
#define VOLGRAPH_ATMOSPHERE_LUT_GLSL

#include "atmosphere.glsl"

const float ATMOSPHERE_PI = 3.14159265358979323846;

// Bruneton 2017, GetTextureCoordFromUnitRange / GetUnitRangeFromTextureCoord.
float texture_coord_from_unit_range(float x, int texture_size) {
  return 0.5 / float(texture_size) + x * (1.0 - 1.0 / float(texture_size));
}
float unit_range_from_texture_coord(float u, int texture_size) {
  return (u - 0.5 / float(texture_size)) / (1.0 - 1.0 / float(texture_size));
}

// H = √(top² − bottom²) and ρ = √(r² − bottom²), from the altitudes.
float horizon_to_top(AtmosphereParameters a) { return sqrt(max(sphere_constant_term(atmosphere_top(a), atmosphere_bottom(a)), 0.0)); }
float distance_to_horizon(AtmosphereParameters a, float r) { return sqrt(max(sphere_constant_term(r, atmosphere_bottom(a)), 0.0)); }

// Bruneton 2017, GetTransmittanceTextureUvFromRMu.
vec2 transmittance_lut_uv(AtmosphereParameters a, float r, float mu, ivec2 size) {
  const float H = horizon_to_top(a), rho = distance_to_horizon(a, r);
  const float d = distance_to_top(a, r, mu), d_min = atmosphere_top(a) - r, d_max = rho + H;
  const float x_mu = d_max > d_min ? clamp((d - d_min) / (d_max - d_min), 0.0, 1.0) : 0.0;
  const float x_r = H > 0.0 ? clamp(rho / H, 0.0, 1.0) : 0.0;
  return vec2(texture_coord_from_unit_range(x_mu, size.x), texture_coord_from_unit_range(x_r, size.y));
}

// Bruneton 2017, GetRMuFromTransmittanceTextureUv: returns (r, mu).
vec2 transmittance_lut_r_mu(AtmosphereParameters a, vec2 uv, ivec2 size) {
  const float x_mu = clamp(unit_range_from_texture_coord(uv.x, size.x), 0.0, 1.0);
  const float x_r = clamp(unit_range_from_texture_coord(uv.y, size.y), 0.0, 1.0);
  const float H = horizon_to_top(a), rho = H * x_r;
  const float bottom = atmosphere_bottom(a);
  const float r = sqrt(rho * rho + bottom * bottom);
  const float d_min = atmosphere_top(a) - r, d_max = rho + H;
  const float d = d_min + x_mu * (d_max - d_min);
  if (d <= 0.0) return vec2(r, 1.0);
  return vec2(r, clamp((H * H - rho * rho - d * d) / (2.0 * r * d), -1.0, 1.0));
}

// Hillaire 2020, GetMultipleScattering: (mu_s · 0.5 + 0.5, altitude / thickness).
vec2 multiscattering_lut_uv(AtmosphereParameters a, float r, float mu_s, ivec2 size) {
  const float x_mu_s = clamp(mu_s * 0.5 + 0.5, 0.0, 1.0);
  const float x_r = clamp((r - atmosphere_bottom(a)) / (atmosphere_top(a) - atmosphere_bottom(a)), 0.0, 1.0);
  return vec2(texture_coord_from_unit_range(x_mu_s, size.x), texture_coord_from_unit_range(x_r, size.y));
}

// Returns (r, mu_s).
vec2 multiscattering_lut_r_mu_s(AtmosphereParameters a, vec2 uv, ivec2 size) {
  const float x_mu_s = clamp(unit_range_from_texture_coord(uv.x, size.x), 0.0, 1.0);
  const float x_r = clamp(unit_range_from_texture_coord(uv.y, size.y), 0.0, 1.0);
  return vec2(atmosphere_bottom(a) + x_r * (atmosphere_top(a) - atmosphere_bottom(a)), 2.0 * x_mu_s - 1.0);
}

// β, the angle between the nadir and the horizon (Hillaire 2020, SkyViewLutParamsToUv).
float horizon_beta(AtmosphereParameters a, float r) {
  return acos(clamp(distance_to_horizon(a, r) / max(r, atmosphere_bottom(a)), 0.0, 1.0));
}

// Hillaire 2020, SkyViewLutParamsToUv: direction = (mu, cos_azimuth).
vec2 sky_view_lut_uv(AtmosphereParameters a, float r, vec2 direction, ivec2 size) {
  const float beta = horizon_beta(a, r), zenith_horizon = ATMOSPHERE_PI - beta;
  const float theta = acos(clamp(direction.x, -1.0, 1.0));
  float v;
  if (!ray_hits_ground(a, r, direction.x)) {
    v = 0.5 * (1.0 - sqrt(max(1.0 - theta / zenith_horizon, 0.0)));
  } else {
    v = 0.5 * (1.0 + sqrt(clamp((theta - zenith_horizon) / beta, 0.0, 1.0)));
  }
  const float u = sqrt(clamp(0.5 - 0.5 * direction.y, 0.0, 1.0));
  return vec2(texture_coord_from_unit_range(u, size.x), texture_coord_from_unit_range(v, size.y));
}

// Hillaire 2020, UvToSkyViewLutParams: returns (mu, cos_azimuth).
vec2 sky_view_lut_direction(AtmosphereParameters a, float r, vec2 uv, ivec2 size) {
  const float x = clamp(unit_range_from_texture_coord(uv.x, size.x), 0.0, 1.0);
  const float y = clamp(unit_range_from_texture_coord(uv.y, size.y), 0.0, 1.0);
  const float beta = horizon_beta(a, r), zenith_horizon = ATMOSPHERE_PI - beta;
  float theta;
  if (y < 0.5) {
    const float above = 1.0 - 2.0 * y;
    theta = zenith_horizon * (1.0 - above * above);
  } else {
    const float below = 2.0 * y - 1.0;
    theta = zenith_horizon + beta * below * below;
  }
  return vec2(cos(theta), 1.0 - 2.0 * x * x);
}

#endif
