#version 450
#extension GL_GOOGLE_include_directive : require
// sky, variant bruneton: where the depth is at the far plane, the sky from Bruneton 2017's
// precomputed scattering and single Mie tables in the pixel's direction (include/atmosphere_bruneton.glsl:
// GetSkyRadiance, a camera above the atmosphere entering it first), plus the sun's disk
// through the transmittance LUT (include/atmosphere_sky_lookup.glsl) and the Lambertian
// ground lit by the sun and the sky's irradiance table (GetSunAndSkyIrradiance) times the
// transmittance to it, all times the sun's irradiance; elsewhere the scene's colour.
#include "include/atmosphere_bruneton.glsl"
#include "include/atmosphere_sky_frame.glsl"
#include "include/bruneton_table_params.h"

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform Frame { SkyPassFrame f; } frame;
layout(set = 0, binding = 3) uniform texture2D depth;
layout(set = 0, binding = 4) uniform sampler nearest;
layout(set = 0, binding = 5) uniform texture2D transmittance;
// The variant's own inputs (passes/atmosphere/sky.cpp variant_inputs), then its table's shape.
layout(set = 0, binding = 8) uniform texture3D scattering;
layout(set = 0, binding = 9) uniform texture3D single_mie_scattering;
layout(set = 0, binding = 10) uniform texture2D irradiance;
layout(set = 0, binding = 11) uniform BrunetonTableParamsBlock { BrunetonTableParams table; };

// The Lambertian ground where the ray (r, mu) meets it, per unit E: albedo / π × (the sun's
// and the sky's irradiance there) × the transmittance to it (Bruneton 2017's demo ground).
vec3 bruneton_ground(AtmosphereParameters a, float r, float mu, float mu_s, float nu) {
  if (!bruneton_enter(a, r, mu, mu_s, nu)) return vec3(0.0);
  r = bruneton_clamp_radius(a, r);
  if (!ray_hits_ground(a, r, mu)) return vec3(0.0);
  const float d = bruneton_ground_distance(a, r, mu);
  const float mu_s_ground = clamp((r * mu_s + d * nu) / atmosphere_bottom(a), -1.0, 1.0);
  const BrunetonIrradiance e =
      bruneton_sun_and_sky_irradiance(a, transmittance, irradiance, nearest, atmosphere_bottom(a), mu_s_ground, 1.0, mu_s_ground);
  return a.ground_albedo.rgb / ATMOSPHERE_PI * (e.sun + e.sky) * bruneton_transmittance(a, transmittance, nearest, r, mu, d, true);
}

layout(location = 0) out vec4 sky_color;

void main() {
  const ivec2 size = textureSize(sampler2D(depth, nearest), 0);
  const ivec2 texel = ivec2(gl_FragCoord.xy);
  // Surfaces (and everything without a sun) keep the colour under them.
  if (texelFetch(sampler2D(depth, nearest), texel, 0).r < 1.0 || frame.f.sun.w < 0.5) discard;
  const AtmosphereParameters a = atmosphere.a;
  const vec3 direction = sky_pixel_direction(frame.f, texel, size);
  const SkyViewOptions options = sky_view_options(frame.f);
  const SkyFrame sky = sky_frame(frame.f, false);  // the camera's radius as it is: the lookups enter from space
  const float mu = clamp(dot(direction, sky.up), -1.0, 1.0);
  const float nu = clamp(dot(direction, sky.toward_sun), -1.0, 1.0);
  vec3 radiance = bruneton_sky_radiance(a, transmittance, scattering, single_mie_scattering, nearest, table.size, sky.r, mu, sky.mu_s, nu).radiance;
  radiance = max(radiance, vec3(0.0));
  if (options.sun_disk) radiance += sun_disk_radiance(a, transmittance, nearest, sky, direction, options.angular_radius, options.limb_darkening);
  if (options.ground) radiance += bruneton_ground(a, sky.r, mu, sky.mu_s, nu);
  sky_color = vec4(radiance * frame.f.sun.rgb, 1.0);
}
