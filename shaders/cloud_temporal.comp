#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_temporal (passes/clouds/cloud_temporal.cpp): cloud_march's images, marched for one
// pixel of each update_block × update_block block this frame (Schneider & Vos 2015), rebuilt
// at full resolution. Per pixel: the one marched this frame takes the new value (with
// update_block 1 every pixel is, and it is blended with the reprojected history by
// temporal_blend.glsl, as pixel_temporal does); the others read the last frame's result
// bilinearly where the last frame's camera saw the pixel's point at the clouds' depth (the
// march's `distance` at its block: the opacity-weighted mean distance; the far plane where
// the ray met no layer, or with reprojection at the far plane chosen). Off the last frame,
// or with no history (the first frame), the small image is upsampled: its block's texel.
// Outputs: rgba the clouds (rgb radiance, a transmittance), rgb the transmittance (a the
// history's frame count).
#include "include/fog_frame.glsl"
#include "include/temporal_blend.glsl"
#include "include/temporal_params.h"
#include "include/cloud_temporal_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture2D marched_clouds;
layout(set = 0, binding = 2) uniform texture2D marched_distance;
layout(set = 0, binding = 3) uniform texture2D clouds_history;
layout(set = 0, binding = 4) uniform texture2D transmittance_history;
layout(set = 0, binding = 5) uniform sampler nearest;
layout(set = 0, binding = 6) uniform sampler bilinear;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2D clouds;
layout(set = 0, binding = 8, rgba16f) uniform writeonly image2D cloud_transmittance;
layout(set = 0, binding = 9) uniform TemporalParamsBlock { TemporalParams params; };
layout(set = 0, binding = 10) uniform CloudTemporalBlockBlock { CloudTemporalBlock b; };

// The point pixel `pixel` sees at the clouds' depth `distance` along its unit ray (the far
// plane where the ray met no layer — distance 0 — or with reprojection at the far plane).
vec3 cloud_point(ivec2 pixel, vec2 size, float distance) {
  const vec3 ray = view_ray(frame.f.view, grid_ndc(vec2(pixel), vec2(0.0), size));
  const bool at_clouds = b.depth.x > 0.5 && distance > 0.0;
  const float t = at_clouds ? distance : frame.f.view.forward.w * length(ray);  // the far plane's view depth along the ray
  return frame.f.view.position.xyz + t * normalize(ray);
}

// Where the last frame saw p: xy its texture coordinate; w 1 if in front of that camera and inside its frame.
vec4 last_frame_uv(vec3 p) {
  const vec3 uvz = view_uvz(params.previous_view, p);
  const bool seen = uvz.z > 0.0 && all(greaterThanEqual(uvz.xy, vec2(0.0))) && all(lessThanEqual(uvz.xy, vec2(1.0)));
  return vec4(uvz, seen ? 1.0 : 0.0);
}

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy), size = imageSize(clouds);
  if (any(greaterThanEqual(pixel, size))) return;
  const int n = max(b.block.x, 1);
  const ivec2 small_size = textureSize(sampler2D(marched_clouds, nearest), 0);
  const ivec2 block = min(pixel / n, small_size - 1);
  const vec4 marched = texelFetch(sampler2D(marched_clouds, nearest), block, 0);
  const bool is_marched = all(equal(pixel, block * n + b.block.yz));
  vec4 where = vec4((vec2(pixel) + 0.5) / vec2(size), 0.0, 1.0);
  if (params.blend.z > 0.5) where = last_frame_uv(cloud_point(pixel, vec2(size), texelFetch(sampler2D(marched_distance, nearest), block, 0).r));
  const bool has_history = params.blend.y > 0.5 && where.w > 0.5;
  vec4 last = marched, count = vec4(0.0);
  if (has_history) {
    last = texture(sampler2D(clouds_history, bilinear), where.xy);
    count = texture(sampler2D(transmittance_history, bilinear), where.xy);
  }
  vec4 result;
  float frames = 1.0;
  if (n == 1) {  // every pixel marched: pixel_temporal's moving average
    const vec4 radiance = temporal_blend(vec4(marched.rgb, 1.0), vec4(last.rgb, count.a), has_history, params.blend.x);
    const vec4 through = temporal_blend(vec4(marched.aaa, 1.0), vec4(last.aaa, count.a), has_history, params.blend.x);
    result = vec4(radiance.rgb, through.r);
    frames = radiance.a;
  } else {  // the marched pixel new, the others the history reprojected (or the block's texel without one)
    result = is_marched ? marched : last;
  }
  const float t = clamp(result.a, 0.0, 1.0);
  imageStore(clouds, pixel, vec4(clamp(result.rgb, vec3(0.0), vec3(65000.0)), t));
  imageStore(cloud_transmittance, pixel, vec4(t, t, t, frames));
}
