// cloud_march (passes/clouds/cloud_march.cpp; wrapped by cloud_march.comp, and by
// cloud_march_weather.comp with CLOUD_WEATHER_MAP: the weather map bound; the variant
// transmittance_map by cloud_march_transmittance_map.comp and cloud_march_weather_transmittance_map.comp
// with CLOUD_TRANSMITTANCE_MAP: the sun's optical depth read from cloud_shadow_map's
// optical_depth_layers, the secondary march only outside it; with CLOUD_PHASE_TABLE, in the
// cloud_march*_phase_table.comp wrappers: the phase read from cloud_phase_table's texture
// instead of the dual-lobe HG): per pixel, the view ray through the cloud
// layer (Schneider & Vos 2015; RTR4 14.4.2): the segment between the layer's two spheres
// (clipped by the scene's surface and max_distance), marched in `steps` equal steps with
// empty-space skipping (coarse steps of 2 × the step on the base density until some is
// found, then one coarse step back and fine steps), a secondary march of `light_steps`
// toward the sun per fine sample, the lighting of shaders/include/cloud_lighting.h, and
// Hillaire's energy-conserving step. Writes rgb the in-scattered radiance, a the
// transmittance (and the transmittance again as rgb in a second image for fog_apply), and
// the transmittance-weighted mean distance of what the layer sends (the clouds' depth for
// aerial perspective and reprojection: Hillaire 2016's cloud depth).
#include "include/cloud_density.h"
#include "include/cloud_lighting.h"
#include "include/depth_buffer.glsl"
#include "include/view_rays.glsl"
#include "include/cloud_march_params.h"
#ifdef CLOUD_TRANSMITTANCE_MAP
#include "include/cloud_shadow_view.h"
#endif
#ifdef CLOUD_PHASE_TABLE
#include "include/cloud_phase_table.h"
#endif

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform CloudMarchParamsBlock { CloudMarchParams params; };
layout(set = 0, binding = 1) uniform texture2D scene_depth;
layout(set = 0, binding = 2) uniform sampler nearest;
layout(set = 0, binding = 3) uniform texture3D shape;
layout(set = 0, binding = 4) uniform texture3D detail;
layout(set = 0, binding = 5) uniform texture2D curl;
layout(set = 0, binding = 6) uniform sampler noise;  // linear, repeat: the textures tile
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2D clouds;
layout(set = 0, binding = 8, rgba16f) uniform writeonly image2D cloud_transmittance;
layout(set = 0, binding = 9, r32f) uniform writeonly image2D cloud_distance;
#ifdef CLOUD_WEATHER_MAP
layout(set = 0, binding = 10) uniform texture2D weather;  // cloud_weather_map.weather: r coverage, g type, a type weight
#endif
#ifdef CLOUD_TRANSMITTANCE_MAP
layout(set = 0, binding = 11) uniform texture3D sun_optical_depth;  // cloud_shadow_map.optical_depth_layers: r τ to the layer's top
layout(set = 0, binding = 12) uniform SunOpticalDepthViewBlock { CloudShadowView view; } sun_optical_depth_view;
layout(set = 0, binding = 13) uniform sampler map_linear;  // linear, clamp: trilinear within the map
#endif
#ifdef CLOUD_PHASE_TABLE
layout(set = 0, binding = 14) uniform texture2D phase_table;  // cloud_phase_table.phase: rgb p(θ_i), rgba32float (fetched)
#endif

const float NEGLIGIBLE = 1e-3;    // early termination: below this transmittance nothing behind shows (kept, not zeroed)
const float HALF_MAX = 65504.0;   // rgba16f's largest value
const int EMPTY_FINE_STEPS = 6;   // fine samples without cloud before the march goes coarse again

#include "include/cloud_layer.glsl"

// Whether the ray from o (at altitude h) along d meets the ground ahead.
bool hits_ground(vec3 o, vec3 d, float h) {
  float t0, t1;
  return h >= 0.0 && sphere_roots(o, d, h, 0.0, t0, t1) && t1 > 0.0;
}

// The segment [t_in, t_out] of the ray inside the layer (the first one), or false.
bool layer_segment(vec3 o, vec3 d, out float t_in, out float t_out) {
  const float h = altitude(o), bottom = params.layer.x, top = params.layer.y;
  float b0, b1, u0, u1;
  const bool meets_bottom = sphere_roots(o, d, h, bottom, b0, b1);
  const bool meets_top = sphere_roots(o, d, h, top, u0, u1);
  if (h < bottom) {  // below: up through the bottom sphere, out through the top
    if (hits_ground(o, d, h) || !meets_bottom || !meets_top) return false;
    t_in = b1;
    t_out = u1;
  } else if (h <= top) {  // inside: to the bottom sphere ahead, else out through the top
    t_in = 0.0;
    t_out = (meets_bottom && b0 > 0.0) ? b0 : (meets_top ? u1 : 0.0);
  } else {  // above: in through the top, out through the bottom (or the top again)
    if (!meets_top || u0 <= 0.0) return false;
    t_in = u0;
    t_out = (meets_bottom && b0 > 0.0) ? b0 : u1;
  }
  return t_out > t_in;
}

// The optical depth toward the sun from p by the secondary march: `light_steps` samples
// over the light march's length.
float marched_sun_optical_depth(vec3 p) {
  const vec3 to_sun = params.sun.xyz;
  const int n = max(params.steps.y, 1);
  const float ds = params.scales.w / float(n);
  float tau = 0.0;
  for (int j = 0; j < n; ++j) tau += cloud_extinction(params.cloud.z, density(p + (float(j) + 0.5) * ds * to_sun)) * ds;
  return tau;
}

#ifdef CLOUD_TRANSMITTANCE_MAP
// The transmittance map's τ at p (Schneider & Vos 2015): p's column (carried along to_sun
// onto the bottom plane, cloud_shadow_lookup.glsl's rule) and p's altitude fraction, read
// trilinearly (slice k's centre at (k + ½)/N: the fraction itself); outside the map (or
// with its sun below the horizon) the secondary march.
float sun_optical_depth_at(vec3 p) {
  const CloudShadowView view = sun_optical_depth_view.view;
  if (view.to_sun.y <= 0.0) return marched_sun_optical_depth(p);
  const float s = (view.plane.y - p.y) / view.to_sun.y;
  const vec2 uv = (p.xz + s * view.to_sun.xz - view.plane.xz) / view.plane.w + 0.5;
  const float f = cloud_height_fraction(altitude(p), params.layer.x, params.layer.y);
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return marched_sun_optical_depth(p);
  return textureLod(sampler3D(sun_optical_depth, map_linear), vec3(uv, f), 0.0).r;  // level 0: no derivatives (WGSL)
}
#else
float sun_optical_depth_at(vec3 p) { return marched_sun_optical_depth(p); }
#endif

// The optical depth toward the sun from p, infinite where the ground hides the sun.
float optical_depth_toward_sun(vec3 p) {
  if (hits_ground(p, params.sun.xyz, altitude(p))) return 1e30;
  return sun_optical_depth_at(p);
}

#ifdef CLOUD_PHASE_TABLE
// The table's p at cos θ per channel: its two texels around θ mixed (cloud_phase_table.h).
vec3 phase_table_at(float cos_theta) {
  const int n = textureSize(sampler2D(phase_table, nearest), 0).x;
  const float x = cloud_phase_table_position(cos_theta, n);
  const vec3 lower = texelFetch(sampler2D(phase_table, nearest), ivec2(cloud_phase_table_lower(x), 0), 0).rgb;
  const vec3 upper = texelFetch(sampler2D(phase_table, nearest), ivec2(cloud_phase_table_upper(x, n), 0), 0).rgb;
  return cloud_phase_table_mix(lower, upper, x);
}

// The sun's octaves (RTR4 eq. 14.18) through the table's phase, read once per ray (one θ: the sun is directional).
vec3 ray_phase;
void begin_ray_phase(float cos_theta) { ray_phase = phase_table_at(cos_theta); }
vec3 sun_octaves(float sigma_s, float tau, float cos_theta) {
  return cloud_octaves_tabulated(sigma_s, tau, ray_phase, params.steps.z, params.octave.x, params.octave.y, params.octave.z);
}
#else
// The sun's octaves (RTR4 eq. 14.18) through the dual-lobe HG.
void begin_ray_phase(float cos_theta) {}
vec3 sun_octaves(float sigma_s, float tau, float cos_theta) {
  return vec3(cloud_octaves(sigma_s, tau, cos_theta, params.lobes.x, params.lobes.y, params.lobes.z, params.steps.z, params.octave.x,
                            params.octave.y, params.octave.z));
}
#endif

// Radiance per metre the cloud sends toward the camera at p (density > 0): the sun through
// the phase and Wrenninge's octaves (RTR4 eq. 14.18), the powder term when on, and the
// ambient radiance scattered isotropically (∫ p dω = 1).
vec3 source(vec3 p, float rho, float cos_theta) {
  const float sigma_s = cloud_scattering(params.cloud.z, rho);
  vec3 s = params.ambient.rgb * sigma_s;
  if (params.sun.w > 0.5) {
    const float tau = optical_depth_toward_sun(p);
    if (tau < 1e29) {
      s += params.sun_irradiance.rgb * sun_octaves(sigma_s, tau, cos_theta) * cloud_powder(tau, params.octave.w);
    }
  }
  return s;
}

// The march's running sums: radiance, transmittance and the distances weighted by the
// opacity each step adds (Σ (T_before − T_after)·t: their mean is the clouds' depth).
struct MarchSums {
  vec3 radiance;
  float transmittance;
  float weighted_distance;
};

// Hillaire 2015's energy-conserving step (RTR4 eq. 14.16) for a grey extinction, at distance t.
void integrate(inout MarchSums sums, vec3 s, float sigma_t, float dt, float t) {
  const float step_t = exp(-sigma_t * dt);
  const vec3 s_int = sigma_t > 0.0 ? (s - s * step_t) / sigma_t : s * dt;
  sums.radiance += sums.transmittance * s_int;
  sums.weighted_distance += sums.transmittance * (1.0 - step_t) * t;
  sums.transmittance *= step_t;
}

// Interleaved gradient noise (Jimenez 2014), scrolled by 5.588238 pixels a frame: in [0, 1)
// (raymarch_fog_body.glsl's): banding at cloud edges becomes noise a temporal pass averages.
float interleaved_gradient_noise(vec2 pixel, float frame_index) {
  const vec2 p = pixel + 5.588238 * mod(frame_index, 64.0);
  return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}

// Where inside each fine step this pixel samples, in [0, 1): its midpoint without jitter.
float step_jitter(ivec2 texel) {
  if (params.steps.w == 0) return 0.5;
  return interleaved_gradient_noise(vec2(texel), params.wind.w);
}

// The march over [t_in, t_out]: coarse steps (2 × dt) on the base density until it is
// non-zero, then one coarse step back and fine steps; back to coarse after
// EMPTY_FINE_STEPS empty fine samples. Stops when the transmittance is negligible.
void march(vec3 o, vec3 d, float t_in, float t_out, float jitter, inout MarchSums sums) {
  const int steps = max(params.steps.x, 1);
  const float dt = (t_out - t_in) / float(steps);
  const float cos_theta = dot(params.sun.xyz, d);  // the light's travel −sun against the scattered −d
  begin_ray_phase(cos_theta);
  float t = t_in;
  bool coarse = true;
  int empty = 0;
  for (int i = 0; i < 4 * steps + 8 && t < t_out; ++i) {
    if (coarse) {
      const vec3 p = o + (t + dt) * d;  // the middle of a coarse step
      if (base_density(p, cloud_height_fraction(altitude(p), params.layer.x, params.layer.y)) > 0.0) {
        coarse = false;  // found: sample this coarse step again, finely
        empty = 0;
        continue;
      }
      t += 2.0 * dt;
      continue;
    }
    const float h = min(dt, t_out - t);
    const float ts = t + jitter * h;
    const vec3 p = o + ts * d;
    const float rho = density(p);
    if (rho > 0.0) {
      empty = 0;
      integrate(sums, source(p, rho, cos_theta), cloud_extinction(params.cloud.z, rho), h, ts);
      if (sums.transmittance < NEGLIGIBLE) return;
    } else if (++empty >= EMPTY_FINE_STEPS) {
      coarse = true;
    }
    t += h;
  }
}

// No NaN or infinity leaves the pass: radiance in [0, half's largest], transmittance in [0, 1].
// Ordered comparisons are false for NaN, so a NaN takes the fallback (WGSL has no isnan).
float finite_in(float v, float hi, float fallback) { return (v >= 0.0 && v <= hi) ? v : (v > hi ? hi : fallback); }
vec3 finite_radiance(vec3 l) { return vec3(finite_in(l.r, HALF_MAX, 0.0), finite_in(l.g, HALF_MAX, 0.0), finite_in(l.b, HALF_MAX, 0.0)); }
float finite_transmittance(float t) { return finite_in(t, 1.0, t < 0.0 ? 0.0 : 1.0); }

// The clouds' depth: the opacity-weighted mean distance of the march's samples; where
// nothing was extinguished the layer's entry (0 where the ray misses the layer).
float mean_distance(MarchSums sums, float t_in, float t_out) {
  const float opacity = 1.0 - sums.transmittance;
  const float t = opacity > 1e-6 ? sums.weighted_distance / opacity : (t_out > t_in ? t_in : 0.0);
  return finite_in(t, 3.0e38, 0.0);
}

// The full-resolution pixel small texel `texel` marches this frame: with update_block B, the
// pixel of its B × B block this frame's Bayer entry names (Schneider & Vos 2015); B = 1: itself.
ivec2 marched_pixel(ivec2 texel) { return texel * params.block.x + params.block.yz; }

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(clouds)))) return;
  const ivec2 size = params.frame.xy, pixel = min(marched_pixel(texel), size - 1);
  const ViewRays view = ViewRays(params.view_position, params.view_forward, params.view_right, params.view_up);
  const vec3 ray = view_ray(view, grid_ndc(vec2(pixel), vec2(0.0), vec2(size)));
  const float ray_length = length(ray);
  const vec3 d = ray / ray_length, o = params.view_position.xyz;
  MarchSums sums = MarchSums(vec3(0.0), 1.0, 0.0);
  float t_in = 0.0, t_out = 0.0;
  if (params.cloud.x > 0.0 && layer_segment(o, d, t_in, t_out)) {
    const float depth = covered_depth(scene_depth, nearest, pixel, size);
    const float surface = depth < 1.0 ? linear_view_depth(depth, params.view_position.w, params.view_forward.w) * ray_length : 3.0e38;
    t_out = min(t_out, min(surface, params.cloud.w));
    if (t_out > t_in) march(o, d, t_in, t_out, step_jitter(pixel), sums);
  }
  const float tr = finite_transmittance(sums.transmittance);
  imageStore(clouds, texel, vec4(finite_radiance(sums.radiance), tr));
  imageStore(cloud_transmittance, texel, vec4(tr, tr, tr, 1.0));
  imageStore(cloud_distance, texel, vec4(mean_distance(sums, t_in, t_out), 0.0, 0.0, 0.0));
}
