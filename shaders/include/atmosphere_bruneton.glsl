// Bruneton 2017's precomputed tables in float (ebruneton/precomputed_atmospheric_scattering,
// atmosphere/functions.glsl): the scattering table's (r, mu, mu_s, nu) ↔ 3D texture mapping
// (nu × mu_s packed in x, the horizon split of mu at v = 1/2), the irradiance table's
// (r, mu_s) ↔ uv, and the lookups: the sky radiance, the radiance to a point, the sun's and
// the sky's irradiance. Tables hold values for a sun of unit irradiance. CPU twin:
// physics/atmosphere_bruneton.h — change both together; the mappings and their sources are
// documented there. Every table is read by texelFetch with a nearest sampler and blended
// here (WebGPU filters no 32-bit float texture), as include/atmosphere_transmittance_lookup.glsl.
// Table shapes are ivec4 (nu, mu_s, mu, r); the 3D texture is (nu · mu_s) × mu × r.
#ifndef VOLGRAPH_ATMOSPHERE_BRUNETON_GLSL
#define VOLGRAPH_ATMOSPHERE_BRUNETON_GLSL

#include "atmosphere.glsl"
#include "atmosphere_lut.glsl"
#include "atmosphere_transmittance_lookup.glsl"

// physics::kBrunetonMuSMin: cos 120°, Bruneton 2017's demo for 32-bit textures.
const float BRUNETON_MU_S_MIN = -0.5;

float bruneton_clamp_radius(AtmosphereParameters a, float r) { return clamp(r, atmosphere_bottom(a), atmosphere_top(a)); }

// Bruneton 2017, DistanceToBottomAtmosphereBoundary for a ray known to hit the ground.
float bruneton_ground_distance(AtmosphereParameters a, float r, float mu) {
  return max(sphere_near_root(r * mu, sphere_constant_term(r, atmosphere_bottom(a))), 0.0);
}

// Bruneton 2017, DistanceToNearestAtmosphereBoundary.
float bruneton_nearest_boundary(AtmosphereParameters a, float r, float mu, bool ray_hits_ground) {
  return ray_hits_ground ? bruneton_ground_distance(a, r, mu) : distance_to_top(a, r, mu);
}

// Bruneton 2017, GetScatteringTextureUvwzFromRMuMuSNu's A (the mu_s mapping's constant).
float bruneton_mu_s_constant(AtmosphereParameters a) {
  const float d_min = atmosphere_top(a) - atmosphere_bottom(a), d_max = horizon_to_top(a);
  return (distance_to_top(a, atmosphere_bottom(a), BRUNETON_MU_S_MIN) - d_min) / (d_max - d_min);
}

// Bruneton 2017, GetScatteringTextureUvwzFromRMuMuSNu: vec4(u_nu, u_mu_s, u_mu, u_r).
vec4 bruneton_scattering_uvwz(AtmosphereParameters a, float r, float mu, float mu_s, float nu, bool ray_hits_ground, ivec4 size) {
  const float H = horizon_to_top(a), rho = distance_to_horizon(a, r);
  const float u_r = texture_coord_from_unit_range(H > 0.0 ? clamp(rho / H, 0.0, 1.0) : 0.0, size.w);
  float u_mu;
  if (ray_hits_ground) {
    // The distance to the ground between r − bottom (mu = −1) and ρ (the horizon).
    const float d = bruneton_ground_distance(a, r, mu), d_min = r - atmosphere_bottom(a), d_max = rho;
    const float x = d_max == d_min ? 0.0 : clamp((d - d_min) / (d_max - d_min), 0.0, 1.0);
    u_mu = 0.5 - 0.5 * texture_coord_from_unit_range(x, size.z / 2);
  } else {
    // The distance to the top between top − r (mu = 1) and ρ + H (the horizon).
    const float d = distance_to_top(a, r, mu), d_min = atmosphere_top(a) - r, d_max = rho + H;
    const float x = d_max == d_min ? 0.0 : clamp((d - d_min) / (d_max - d_min), 0.0, 1.0);
    u_mu = 0.5 + 0.5 * texture_coord_from_unit_range(x, size.z / 2);
  }
  // Bruneton 2017's ad-hoc max(1 − a/A, 0) / (1 + a) of the ground's distance to the top toward the sun.
  const float d_min = atmosphere_top(a) - atmosphere_bottom(a), d_max = H;
  const float x_a = (distance_to_top(a, atmosphere_bottom(a), mu_s) - d_min) / (d_max - d_min);
  const float A = bruneton_mu_s_constant(a);
  const float u_mu_s = texture_coord_from_unit_range(clamp(max(1.0 - x_a / A, 0.0) / (1.0 + x_a), 0.0, 1.0), size.y);
  return vec4(clamp((nu + 1.0) * 0.5, 0.0, 1.0), u_mu_s, u_mu, u_r);
}

struct BrunetonParams {
  float r, mu, mu_s, nu;
  bool ray_hits_ground;
};

// Bruneton 2017, GetRMuMuSNuFromScatteringTextureUvwz.
BrunetonParams bruneton_scattering_params(AtmosphereParameters a, vec4 uvwz, ivec4 size) {
  const float H = horizon_to_top(a);
  const float rho = H * clamp(unit_range_from_texture_coord(uvwz.w, size.w), 0.0, 1.0);
  BrunetonParams p;
  p.r = sqrt(rho * rho + atmosphere_bottom(a) * atmosphere_bottom(a));
  if (uvwz.z < 0.5) {
    // The ground half: mu from the distance to the ground.
    const float d_min = p.r - atmosphere_bottom(a), d_max = rho;
    const float d = d_min + (d_max - d_min) * clamp(unit_range_from_texture_coord(1.0 - 2.0 * uvwz.z, size.z / 2), 0.0, 1.0);
    p.mu = d == 0.0 ? -1.0 : clamp(-(rho * rho + d * d) / (2.0 * p.r * d), -1.0, 1.0);
    p.ray_hits_ground = true;
  } else {
    // The sky half: mu from the distance to the top.
    const float d_min = atmosphere_top(a) - p.r, d_max = rho + H;
    const float d = d_min + (d_max - d_min) * clamp(unit_range_from_texture_coord(2.0 * uvwz.z - 1.0, size.z / 2), 0.0, 1.0);
    p.mu = d == 0.0 ? 1.0 : clamp((H * H - rho * rho - d * d) / (2.0 * p.r * d), -1.0, 1.0);
    p.ray_hits_ground = false;
  }
  const float x_mu_s = clamp(unit_range_from_texture_coord(uvwz.y, size.y), 0.0, 1.0);
  const float d_min = atmosphere_top(a) - atmosphere_bottom(a), d_max = H;
  const float A = bruneton_mu_s_constant(a);
  const float x_a = (A - x_mu_s * A) / (1.0 + x_mu_s * A);
  const float d = d_min + min(x_a, A) * (d_max - d_min);
  p.mu_s = d == 0.0 ? 1.0 : clamp((H * H - d * d) / (2.0 * atmosphere_bottom(a) * d), -1.0, 1.0);
  p.nu = clamp(uvwz.x * 2.0 - 1.0, -1.0, 1.0);
  return p;
}

// Bruneton 2017, GetRMuMuSNuFromScatteringTextureFragCoord: texel (x, y, z), nu clamped to
// the range mu and mu_s allow.
BrunetonParams bruneton_scattering_texel_params(AtmosphereParameters a, ivec3 texel, ivec4 size) {
  const int nu_index = texel.x / size.y, mu_s_index = texel.x - nu_index * size.y;
  const vec4 uvwz = vec4(size.x > 1 ? float(nu_index) / float(size.x - 1) : 0.5, (float(mu_s_index) + 0.5) / float(size.y),
                         (float(texel.y) + 0.5) / float(size.z), (float(texel.z) + 0.5) / float(size.w));
  BrunetonParams p = bruneton_scattering_params(a, uvwz, size);
  const float spread = sqrt(max((1.0 - p.mu * p.mu) * (1.0 - p.mu_s * p.mu_s), 0.0));
  p.nu = clamp(p.nu, p.mu * p.mu_s - spread, p.mu * p.mu_s + spread);
  return p;
}

// Bruneton 2017, GetIrradianceTextureUvFromRMuS / GetRMuSFromIrradianceTextureUv (returns (r, mu_s)).
vec2 bruneton_irradiance_uv(AtmosphereParameters a, float r, float mu_s, ivec2 size) {
  const float x_r = clamp((r - atmosphere_bottom(a)) / (atmosphere_top(a) - atmosphere_bottom(a)), 0.0, 1.0);
  const float x_mu_s = clamp(mu_s * 0.5 + 0.5, 0.0, 1.0);
  return vec2(texture_coord_from_unit_range(x_mu_s, size.x), texture_coord_from_unit_range(x_r, size.y));
}
vec2 bruneton_irradiance_r_mu_s(AtmosphereParameters a, vec2 uv, ivec2 size) {
  const float x_mu_s = clamp(unit_range_from_texture_coord(uv.x, size.x), 0.0, 1.0);
  const float x_r = clamp(unit_range_from_texture_coord(uv.y, size.y), 0.0, 1.0);
  return vec2(atmosphere_bottom(a) + x_r * (atmosphere_top(a) - atmosphere_bottom(a)), clamp(2.0 * x_mu_s - 1.0, -1.0, 1.0));
}

// Linear between texel centres, clamped at the edges (physics::BrunetonTable::sample).
vec4 bruneton_fetch3d(texture3D table, sampler nearest, ivec3 texel, ivec3 size) {
  return texelFetch(sampler3D(table, nearest), clamp(texel, ivec3(0), size - 1), 0);
}
vec4 bruneton_fetch2d(texture2D table, sampler nearest, ivec2 texel, ivec2 size) {
  return texelFetch(sampler2D(table, nearest), clamp(texel, ivec2(0), size - 1), 0);
}
vec4 bruneton_sample2d(texture2D table, sampler nearest, vec2 uv) {
  const ivec2 size = textureSize(sampler2D(table, nearest), 0);
  const vec2 x = uv * vec2(size) - 0.5;
  const ivec2 base = ivec2(floor(x));
  const vec2 f = x - vec2(base);
  const vec4 low = mix(bruneton_fetch2d(table, nearest, base, size), bruneton_fetch2d(table, nearest, base + ivec2(1, 0), size), f.x);
  const vec4 high = mix(bruneton_fetch2d(table, nearest, base + ivec2(0, 1), size), bruneton_fetch2d(table, nearest, base + ivec2(1, 1), size), f.x);
  return mix(low, high, f.y);
}

// Between two mu_s texels of the scattering tables: geometric where both are positive, else
// linear (rgb; alpha linear). Near the horizon a texel's scattering falls about as
// e^(−τ/mu_s) with the sun's air mass, which a linear blend overestimates (volgraph's
// departure from Bruneton 2017's hardware filter: the sunset horizon's worst pixel 3.1 % →
// 0.9 % at the default table; physics::BrunetonTable::sample_scattering is its CPU twin).
vec4 bruneton_mix_mu_s(vec4 low, vec4 high, float f) {
  vec4 result = mix(low, high, f);
  for (int c = 0; c < 3; ++c) {
    if (low[c] > 0.0 && high[c] > 0.0) result[c] = exp(mix(log(low[c]), log(high[c]), f));
  }
  return result;
}
// A scattering table's 3D lookup: linear in mu (y) and r (z), bruneton_mix_mu_s in mu_s (x).
vec4 bruneton_sample_scattering3d(texture3D table, sampler nearest, vec3 uvw) {
  const ivec3 size = textureSize(sampler3D(table, nearest), 0);
  const vec3 x = uvw * vec3(size) - 0.5;
  const ivec3 base = ivec3(floor(x));
  const vec3 f = x - vec3(base);
  vec4 layers[2];
  for (int k = 0; k < 2; ++k) {
    const vec4 low = bruneton_mix_mu_s(bruneton_fetch3d(table, nearest, base + ivec3(0, 0, k), size),
                                       bruneton_fetch3d(table, nearest, base + ivec3(1, 0, k), size), f.x);
    const vec4 high = bruneton_mix_mu_s(bruneton_fetch3d(table, nearest, base + ivec3(0, 1, k), size),
                                        bruneton_fetch3d(table, nearest, base + ivec3(1, 1, k), size), f.x);
    layers[k] = mix(low, high, f.y);
  }
  return mix(layers[0], layers[1], f.z);
}

// Bruneton 2017, GetScattering: a 4D lookup as two 3D ones, blended between the nu slices.
vec4 bruneton_scattering(AtmosphereParameters a, texture3D table, sampler nearest, ivec4 size, float r, float mu, float mu_s, float nu,
                         bool ray_hits_ground) {
  const vec4 uvwz = bruneton_scattering_uvwz(a, r, mu, mu_s, nu, ray_hits_ground, size);
  const float coord = uvwz.x * float(size.x - 1);
  const float slice = min(floor(coord), float(max(size.x - 2, 0)));
  const float lerp = clamp(coord - slice, 0.0, 1.0);
  const vec3 uvw0 = vec3((slice + uvwz.y) / float(size.x), uvwz.z, uvwz.w);
  const vec3 uvw1 = vec3((slice + 1.0 + uvwz.y) / float(size.x), uvwz.z, uvwz.w);
  return mix(bruneton_sample_scattering3d(table, nearest, uvw0), bruneton_sample_scattering3d(table, nearest, uvw1), lerp);
}

// Bruneton 2017, GetIrradiance.
vec3 bruneton_irradiance(AtmosphereParameters a, texture2D table, sampler nearest, float r, float mu_s) {
  const ivec2 size = textureSize(sampler2D(table, nearest), 0);
  return bruneton_sample2d(table, nearest, bruneton_irradiance_uv(a, r, mu_s, size)).rgb;
}

// Bruneton 2017, GetTransmittance: between (r, mu) and d along its ray, from two transmittances to the top.
vec3 bruneton_transmittance(AtmosphereParameters a, texture2D lut, sampler nearest, float r, float mu, float d, bool ray_hits_ground) {
  const float r_d = bruneton_clamp_radius(a, radius_at(r, mu, d));
  const float mu_d = clamp((r * mu + d) / r_d, -1.0, 1.0);
  const vec3 near = ray_hits_ground ? transmittance_lookup(a, lut, nearest, r_d, -mu_d) : transmittance_lookup(a, lut, nearest, r, mu);
  const vec3 far = ray_hits_ground ? transmittance_lookup(a, lut, nearest, r, -mu) : transmittance_lookup(a, lut, nearest, r_d, mu_d);
  return vec3(far.r > 0.0 ? min(near.r / far.r, 1.0) : 0.0, far.g > 0.0 ? min(near.g / far.g, 1.0) : 0.0,
              far.b > 0.0 ? min(near.b / far.b, 1.0) : 0.0);
}

// Rayleigh rgb · p_R(nu) + Mie rgb · p_M(nu) (Bruneton 2017, GetSkyRadiance's return).
vec3 bruneton_with_phases(AtmosphereParameters a, vec3 rayleigh, vec3 mie, float nu) {
  return rayleigh * phase_rayleigh(nu) + mie * mie_phase(a, nu);
}

// A camera above the atmosphere moves to the top along its ray (Bruneton 2017, GetSkyRadiance's
// first lines, in (r, mu, mu_s, nu)): false when the ray misses the atmosphere.
bool bruneton_enter(AtmosphereParameters a, inout float r, inout float mu, inout float mu_s, float nu) {
  if (r <= atmosphere_top(a)) return true;
  const float d = enter_atmosphere(a, r, mu);
  if (d < 0.0) return false;
  const float top = atmosphere_top(a);
  mu = clamp((r * mu + d) / top, -1.0, 1.0);
  mu_s = clamp((r * mu_s + d * nu) / top, -1.0, 1.0);
  r = top;
  return true;
}

// Radiance per unit E toward the camera and the transmittance.
struct BrunetonRadiance {
  vec3 radiance;
  vec3 transmittance;
};

// Bruneton 2017, GetSkyRadiance (no light shafts; separate scattering and single Mie
// textures): the camera at radius r, the view at zenith cosine mu and at cosine nu from the
// sun, the sun at zenith cosine mu_s.
BrunetonRadiance bruneton_sky_radiance(AtmosphereParameters a, texture2D transmittance_lut, texture3D scattering,
                                       texture3D single_mie_scattering, sampler nearest, ivec4 size, float r, float mu, float mu_s,
                                       float nu) {
  BrunetonRadiance result = BrunetonRadiance(vec3(0.0), vec3(1.0));
  if (!bruneton_enter(a, r, mu, mu_s, nu)) return result;
  r = bruneton_clamp_radius(a, r);
  const bool hits_ground = ray_hits_ground(a, r, mu);
  result.transmittance = hits_ground ? vec3(0.0) : transmittance_lookup(a, transmittance_lut, nearest, r, mu);
  const vec3 s = bruneton_scattering(a, scattering, nearest, size, r, mu, mu_s, nu, hits_ground).rgb;
  const vec3 mie = bruneton_scattering(a, single_mie_scattering, nearest, size, r, mu, mu_s, nu, hits_ground).rgb;
  result.radiance = bruneton_with_phases(a, s, mie, nu);
  return result;
}

// Bruneton 2017, GetSkyRadianceToPoint (no light shafts; separate scattering and single Mie
// textures): S(camera) − T · S(point) over the first d m of the ray.
BrunetonRadiance bruneton_sky_radiance_to_point(AtmosphereParameters a, texture2D transmittance_lut, texture3D scattering,
                                                texture3D single_mie_scattering, sampler nearest, ivec4 size, float r, float mu,
                                                float mu_s, float nu, float d) {
  BrunetonRadiance result = BrunetonRadiance(vec3(0.0), vec3(1.0));
  if (!(d > 0.0)) return result;
  // From space, the part of the ray before the top holds no air.
  if (r > atmosphere_top(a)) d = max(d - max(enter_atmosphere(a, r, mu), 0.0), 0.0);
  if (!bruneton_enter(a, r, mu, mu_s, nu)) return result;
  r = bruneton_clamp_radius(a, r);
  const bool hits_ground = ray_hits_ground(a, r, mu);
  result.transmittance = bruneton_transmittance(a, transmittance_lut, nearest, r, mu, d, hits_ground);
  const float r_p = bruneton_clamp_radius(a, radius_at(r, mu, d));
  const float mu_p = clamp((r * mu + d) / r_p, -1.0, 1.0), mu_s_p = clamp((r * mu_s + d * nu) / r_p, -1.0, 1.0);
  const vec3 s = bruneton_scattering(a, scattering, nearest, size, r, mu, mu_s, nu, hits_ground).rgb;
  const vec3 s_p = bruneton_scattering(a, scattering, nearest, size, r_p, mu_p, mu_s_p, nu, hits_ground).rgb;
  const vec3 m = bruneton_scattering(a, single_mie_scattering, nearest, size, r, mu, mu_s, nu, hits_ground).rgb;
  const vec3 m_p = bruneton_scattering(a, single_mie_scattering, nearest, size, r_p, mu_p, mu_s_p, nu, hits_ground).rgb;
  // Bruneton 2017's smoothstep on single Mie against artefacts with the sun below the horizon.
  const vec3 mie = (m - result.transmittance * m_p) * smoothstep(0.0, 0.01, mu_s);
  result.radiance = bruneton_with_phases(a, s - result.transmittance * s_p, mie, nu);
  return result;
}

// Bruneton 2017, GetSunAndSkyIrradiance at radius r on a surface whose normal has zenith
// cosine normal_up and cosine normal_sun with the sun: (sun, sky) per unit E.
struct BrunetonIrradiance {
  vec3 sun;
  vec3 sky;
};
BrunetonIrradiance bruneton_sun_and_sky_irradiance(AtmosphereParameters a, texture2D transmittance_lut, texture2D irradiance,
                                                   sampler nearest, float r, float mu_s, float normal_up, float normal_sun) {
  r = bruneton_clamp_radius(a, r);
  BrunetonIrradiance result;
  result.sky = bruneton_irradiance(a, irradiance, nearest, r, mu_s) * (1.0 + normal_up) * 0.5;
  result.sun = sun_transmittance_lookup(a, transmittance_lut, nearest, r, mu_s) * max(normal_sun, 0.0);
  return result;
}

#endif
