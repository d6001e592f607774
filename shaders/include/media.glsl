// Participating media maths shared by every fog technique, per RGB channel. CPU twin:
// physics/media.h — change both together; formulas and precision notes there.
#ifndef VOLGRAPH_MEDIA_GLSL
#define VOLGRAPH_MEDIA_GLSL

const float SERIES_BELOW = 0.01;
const float MAX_EXPONENT = 80.0;
const float MIN_TRANSMITTANCE = 1e-6;
// Marches stop once every channel's transmittance is below this: what lies behind adds at
// most this fraction of its own radiance.
const float NEGLIGIBLE_TRANSMITTANCE = 1e-4;

// (1 − e^(−x)) / x, a series below |x| = SERIES_BELOW (the direct form cancels there).
float one_minus_exp_over_x(float x) {
  x = max(x, -MAX_EXPONENT);
  if (abs(x) < SERIES_BELOW) return 1.0 + x * (-1.0 / 2.0 + x * (1.0 / 6.0 + x * (-1.0 / 24.0 + x / 120.0)));
  return (1.0 - exp(-x)) / x;
}
vec3 one_minus_exp_over_x(vec3 x) {
  return vec3(one_minus_exp_over_x(x.r), one_minus_exp_over_x(x.g), one_minus_exp_over_x(x.b));
}

vec3 transmittance(vec3 sigma_t, float distance) { return exp(-min(sigma_t * distance, vec3(1e30))); }

// ∫₀^len e^(−σt·s) ds = (1 − e^(−σt·len))/σt, stable as σt → 0 (→ len).
vec3 attenuated_length(vec3 sigma_t, float len) { return len * one_minus_exp_over_x(sigma_t * len); }

// Wronski 2014 (eq. 14.15).
void integrate_wronski(inout vec3 radiance, inout vec3 transmittance_so_far, vec3 in_scatter, vec3 sigma_t, float dz) {
  radiance += transmittance_so_far * in_scatter * dz;
  transmittance_so_far *= transmittance(sigma_t, dz);
}

// Hillaire 2015 (eq. 14.16), energy-conserving and stable as σt → 0.
void integrate_hillaire(inout vec3 radiance, inout vec3 transmittance_so_far, vec3 in_scatter, vec3 sigma_t, float dz) {
  radiance += transmittance_so_far * in_scatter * dz * one_minus_exp_over_x(sigma_t * dz);
  transmittance_so_far *= transmittance(sigma_t, dz);
}

// Optical depth through exponential height fog along origin + t·direction, t ∈ [0, length].
vec3 height_fog_optical_depth(vec3 sigma_base, float falloff, float base_height, float origin_y, float direction_y, float len) {
  const float at_origin = exp(min(-falloff * (origin_y - base_height), MAX_EXPONENT));
  return sigma_base * (at_origin * len * one_minus_exp_over_x(falloff * direction_y * len));
}

const float INFINITE_OPTICAL_DEPTH = 1e30;

// The unit-density optical depth from origin_y toward a directional light along
// `direction_y`, to infinity; INFINITE_OPTICAL_DEPTH for a level or downward direction.
float height_fog_unit_depth_to_infinity(float falloff, float base_height, float origin_y, float direction_y) {
  if (!(direction_y > 0.0)) return INFINITE_OPTICAL_DEPTH;
  const float len = MAX_EXPONENT / (falloff * direction_y);
  return min(height_fog_optical_depth(vec3(1.0), falloff, base_height, origin_y, direction_y, len).r, INFINITE_OPTICAL_DEPTH);
}

// ∫₀^len e^(−(a + x·s/len)) ds = len·e^(−a)·(1 − e^(−x))/x per channel: an optical depth
// growing linearly from a by x along the way.
vec3 attenuated_length_from(vec3 depth_at_start, vec3 depth_across, float len) {
  vec3 out_length;
  for (int c = 0; c < 3; ++c) {
    const float a = min(depth_at_start[c], MAX_EXPONENT), x = depth_across[c];
    if (abs(x) < SERIES_BELOW) {
      out_length[c] = len * exp(-a) * one_minus_exp_over_x(x);
    } else {
      const float end = clamp(depth_at_start[c] + x, -MAX_EXPONENT, MAX_EXPONENT);
      out_length[c] = len * (exp(-a) - exp(-end)) / x;
    }
  }
  return out_length;
}

// Depth fog (eq. 14.12–14.14): the fraction of the surface's radiance left at distance z.
float depth_fog_linear(float z, float z_start, float z_end) {
  if (z_end <= z_start) return z < z_start ? 1.0 : 0.0;
  return clamp((z_end - z) / (z_end - z_start), 0.0, 1.0);
}
float depth_fog_exponential(float z, float density) { return exp(-min(density * z, MAX_EXPONENT)); }
float depth_fog_exponential_squared(float z, float density) {
  const float dz = min(density * z, 9.0);
  return exp(-dz * dz);
}

#endif
