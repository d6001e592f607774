// raymarch_fog's body: per output pixel, a march from the camera to the scene's surface
// (or to view depth max_distance where there is none) in `steps` equal steps, each
// sampled at a per-pixel jittered point inside it; at each sample the media
// (media_field.glsl) and their in-scattering (in_scattering.glsl, shared with
// froxel_scatter: the lights through the pass's phase variant, the shadow map's visibility
// and the volumetric shadow toward each light by light_transmittance.glsl), integrated by
// Hillaire's step (media.glsl, eq. 14.16). The including shader defines
// `float light_visibility(int light, vec3 p)` and `bool media_shadow_mapped(int light)`
// (false: every light gets the march) first.
#ifndef VOLGRAPH_RAYMARCH_FOG_BODY_GLSL
#define VOLGRAPH_RAYMARCH_FOG_BODY_GLSL
#include "pixel_fog.glsl"  // bindings 0–4 (the frame block `frame`), the workgroup, store_fog
#include "in_scattering.glsl"
#include "raymarch_params.h"

layout(set = 0, binding = 5) uniform RaymarchParamsBlock { RaymarchParams params; };

const float SOURCE_MAX = 1e30;     // in-scattering is kept finite (a light at a sample point)

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of
// Duty: Advanced Warfare"), scrolled by 5.588238 pixels a frame: in [0, 1).
float interleaved_gradient_noise(vec2 pixel, float frame_index) {
  const vec2 p = pixel + 5.588238 * mod(frame_index, 64.0);
  return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}

// Where inside each step this pixel samples, in [0, 1).
float step_jitter(ivec2 texel) {
  if (params.jitter.x < 0.5) return 0.5;
  return interleaved_gradient_noise(vec2(texel), params.jitter.y);
}

// View depth where the march ends: the surface's, or max_distance where there is none.
float march_end_depth(float depth) {
  if (depth >= 1.0) return params.distances.x;
  return view_depth(frame.f, depth);
}

// Radiance per metre the media send toward the camera at p (DESIGN.md units), kept finite.
vec3 source(MediaSample m, vec3 p, vec3 to_camera, float jitter) {
  const vec3 s = in_scattering(m, p, to_camera, PhaseChoice(params.modes.x, params.lobes.x, params.lobes.y),
                               LightMarch(params.steps.y, params.distances.y, jitter), true);
  return min(s, vec3(SOURCE_MAX));
}

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const ivec2 out_size = imageSize(fog_scattering);
  if (any(greaterThanEqual(texel, out_size))) return;
  const vec3 ray = view_ray(frame.f.view, grid_ndc(vec2(texel), vec2(0.0), vec2(out_size)));
  const float ray_length = length(ray);
  const vec3 direction = ray / ray_length;
  const float dt = march_end_depth(covered_depth(scene_depth, nearest, texel, out_size)) * ray_length / float(params.steps.x);
  const float jitter = step_jitter(texel);
  const vec3 origin = frame.f.view.position.xyz;
  vec3 radiance = vec3(0.0), transmittance_so_far = vec3(1.0);
  // Step k covers [k·dt, (k + 1)·dt] and is sampled at (k + jitter)·dt: the steps tile
  // the ray exactly whatever the jitter, so a homogeneous medium stays exact.
  for (int k = 0; k < params.steps.x; ++k) {
    const vec3 p = origin + (float(k) + jitter) * dt * direction;
    const MediaSample m = sample_media(frame.f.media, p);
    integrate_hillaire(radiance, transmittance_so_far, source(m, p, -direction, jitter), m.sigma_s + m.sigma_a, dt);
    if (all(lessThan(transmittance_so_far, vec3(NEGLIGIBLE_TRANSMITTANCE)))) break;  // nothing behind shows
  }
  store_fog(uvec2(texel), radiance, transmittance_so_far);
}

#endif
