// Reading the sky from the atmosphere's LUTs for a view direction in world space: its
// latitude and azimuth from the sun around the camera into the sky-view LUT (Hillaire 2020
// §5.3), the sun's disk, E / (π sin²α) within its angular radius α (limb-darkened when
// asked), through the transmittance LUT, and the Lambertian ground. CPU twin:
// physics/atmosphere_sky.h (sky_view_direction, limb_darkening, sun_disk_radiance,
// ground_radiance) — change both together.
#ifndef VOLGRAPH_ATMOSPHERE_SKY_LOOKUP_GLSL
#define VOLGRAPH_ATMOSPHERE_SKY_LOOKUP_GLSL

#include "atmosphere_transmittance_lookup.glsl"

// The camera in the planet's frame.
struct SkyFrame {
  vec3 up;          // its local zenith
  float r;          // its radius (clamped to the top's for the sky-view LUT; as it is for a march)
  vec3 toward_sun;  // unit
  float mu_s;       // the sun's zenith cosine there
};

// A world direction as the sky-view LUT holds it: (its zenith cosine, the cosine of its
// azimuth from the sun's).
vec2 sky_view_direction(SkyFrame f, vec3 direction) {
  const float mu = clamp(dot(direction, f.up), -1.0, 1.0);
  const vec3 across = direction - mu * f.up, sun_across = f.toward_sun - f.mu_s * f.up;
  const float lengths = length(across) * length(sun_across);
  return vec2(mu, lengths > 1e-12 ? clamp(dot(across, sun_across) / lengths, -1.0, 1.0) : 1.0);
}

vec3 sky_view_lookup(AtmosphereParameters a, texture2D sky_view, sampler linear, SkyFrame f, vec3 direction) {
  const ivec2 size = textureSize(sampler2D(sky_view, linear), 0);
  return texture(sampler2D(sky_view, linear), sky_view_lut_uv(a, f.r, sky_view_direction(f, direction), size)).rgb;
}

// Hillaire 2016 (Frostbite's sky, appendix B), after Neckel & Labs 1994: I(μ)/I(1) = μ^a
// (u = 1), a = (0.397, 0.503, 0.652) at 680, 550, 440 nm, μ = √(1 − ρ²), ρ = sin θ / sin α,
// times (a + 2) / 2, the inverse of its mean over the disk's projected solid angle: E stays E.
// (sin θ as |d × s|: 1 − cos² loses float's digits this close to the sun.)
vec3 limb_darkening(float rho) {
  if (rho > 1.0) return vec3(0.0);
  const vec3 a = vec3(0.397, 0.503, 0.652);
  return pow(vec3(sqrt(max(0.0, 1.0 - rho * rho))), a) * (a + 2.0) * 0.5;
}

// Per unit E: 1 / (π sin²α) within the disk (a uniform disk of angular radius α gives
// E = L π sin²α), times the limb darkening when asked, times the transmittance toward the
// sun — from where the ray enters the top for a camera above it, 1 when it misses the
// atmosphere —; 0 outside the disk or below the ground.
vec3 sun_disk_radiance(AtmosphereParameters a, texture2D transmittance_lut, sampler nearest, SkyFrame f, vec3 direction,
                       float angular_radius, bool limb_darkened) {
  const float cosine = clamp(dot(direction, f.toward_sun), -1.0, 1.0);
  if (cosine < cos(angular_radius)) return vec3(0.0);
  const float s = sin(angular_radius);
  const vec3 disk = (limb_darkened ? limb_darkening(length(cross(direction, f.toward_sun)) / s) : vec3(1.0)) / (ATMOSPHERE_PI * s * s);
  float r = max(f.r, atmosphere_bottom(a));
  float mu = clamp(dot(direction, f.up), -1.0, 1.0);
  if (r > atmosphere_top(a)) {
    const float entry = enter_atmosphere(a, r, mu);
    if (entry < 0.0) return disk;  // Hillaire 2020: GetSunLuminance in space
    mu = mu_at(r, mu, entry);
    r = atmosphere_top(a);
  }
  if (ray_hits_ground(a, r, mu)) return vec3(0.0);
  return transmittance_lookup(a, transmittance_lut, nearest, r, mu) * disk;
}

vec3 sun_disk_radiance(AtmosphereParameters a, texture2D transmittance_lut, sampler nearest, SkyFrame f, vec3 direction,
                       float angular_radius) {
  return sun_disk_radiance(a, transmittance_lut, nearest, f, direction, angular_radius, false);
}

// The Lambertian ground's radiance per unit E where the sun's zenith cosine is mu_s
// (Bruneton 2017's ground radiance): albedo × (T_sun · max(mu_s, 0) / π + Ψ_ms).
vec3 ground_radiance(AtmosphereParameters a, texture2D transmittance_lut, sampler nearest, float mu_s, vec3 psi) {
  const vec3 sun = mu_s > 0.0 ? sun_transmittance_lookup(a, transmittance_lut, nearest, atmosphere_bottom(a), mu_s) : vec3(0.0);
  return a.ground_albedo.rgb * (sun * max(mu_s, 0.0) / ATMOSPHERE_PI + psi);
}

// The transmittance from (r, mu) to the ground along a ray that hits it, from the LUT:
// T(r_d, −mu_d) / T(r, −mu) (Bruneton 2017, GetTransmittance with ray_r_mu_intersects_ground).
vec3 transmittance_to_ground_lookup(AtmosphereParameters a, texture2D transmittance_lut, sampler nearest, float r, float mu, float d) {
  const float r_d = radius_at(r, mu, d), mu_d = mu_at(r, mu, d);
  const vec3 from_camera = transmittance_lookup(a, transmittance_lut, nearest, r, -mu);
  return min(transmittance_lookup(a, transmittance_lut, nearest, r_d, -mu_d) / max(from_camera, vec3(1e-30)), vec3(1.0));
}

#endif
