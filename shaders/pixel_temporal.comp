#version 450
#extension GL_GOOGLE_include_directive : require
// pixel_temporal: temporal accumulation of a per-pixel fog technique's two images
// (in-scattering, transmittance). Each texel's point — on its ray at the scene's depth
// there, the far plane where nothing was drawn — is reprojected by the last frame's
// camera (view_uvz); the last frame's blended images are read there bilinearly and
// blended with this frame's (temporal_blend.glsl). Where the last frame did not see the
// point — outside its frame, or hidden (the view depth the history keeps in the
// transmittance's alpha disagrees) — and on the first frame, this frame's values pass
// through unchanged (passes/fog/pixel_temporal.cpp). Alpha: the frame count in the
// scattering, the point's view depth (m) in the transmittance.
#include "include/fog_frame.glsl"
#include "include/temporal_blend.glsl"
#include "include/temporal_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture2D scene_depth;
layout(set = 0, binding = 2) uniform texture2D fog_scattering;
layout(set = 0, binding = 3) uniform texture2D fog_transmittance;
layout(set = 0, binding = 4) uniform texture2D scattering_history;
layout(set = 0, binding = 5) uniform texture2D transmittance_history;
layout(set = 0, binding = 6) uniform sampler nearest;
layout(set = 0, binding = 7) uniform sampler bilinear;
layout(set = 0, binding = 8, rgba16f) uniform writeonly image2D accumulated_scattering;
layout(set = 0, binding = 9, rgba16f) uniform writeonly image2D accumulated_transmittance;
layout(set = 0, binding = 10) uniform TemporalParamsBlock { TemporalParams params; };

// This texel's point: on its ray at the scene's depth there (the far plane where
// nothing was drawn). w: its view depth.
vec4 texel_point(ivec2 texel, vec2 size) {
  const ivec2 depth_size = textureSize(sampler2D(scene_depth, nearest), 0);
  const ivec2 depth_texel = min(ivec2((vec2(texel) + 0.5) / size * vec2(depth_size)), depth_size - 1);
  const float z = view_depth(frame.f, texelFetch(sampler2D(scene_depth, nearest), depth_texel, 0).r);
  return vec4(frame.f.view.position.xyz + z * view_ray(frame.f.view, grid_ndc(vec2(texel), vec2(0.0), size)), z);
}

// Where the last frame saw point p: xy its texture coordinate, z its view depth then,
// w 1 if it was in front of that camera and inside its frame.
vec4 last_frame_uv(vec3 p) {
  const vec3 uvz = view_uvz(params.previous_view, p);
  const bool seen = uvz.z > 0.0 && all(greaterThanEqual(uvz.xy, vec2(0.0))) && all(lessThanEqual(uvz.xy, vec2(1.0)));
  return vec4(uvz, seen ? 1.0 : 0.0);
}

// The last frame saw the point itself, not something in front of it (a disocclusion) or
// behind it: the view depth it kept there (bilinear, so mixed across an edge) agrees
// with the point's within 5 %.
bool same_surface(float kept_depth, float expected_depth) {
  return abs(kept_depth - expected_depth) <= 0.05 * expected_depth;
}

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const ivec2 size = imageSize(accumulated_scattering);
  if (any(greaterThanEqual(texel, size))) return;
  const vec4 p = texel_point(texel, vec2(size));
  vec4 where = vec4((vec2(texel) + 0.5) / vec2(size), p.w, 1.0);
  if (params.blend.z > 0.5) where = last_frame_uv(p.xyz);
  vec4 scattered_last = vec4(0.0), through_last = vec4(0.0);
  bool valid = params.blend.y > 0.5 && where.w > 0.5;
  if (valid) {
    scattered_last = texture(sampler2D(scattering_history, bilinear), where.xy);
    through_last = texture(sampler2D(transmittance_history, bilinear), where.xy);
    valid = params.blend.z < 0.5 || same_surface(through_last.a, where.z);
  }
  const vec4 scattered = temporal_blend(texelFetch(sampler2D(fog_scattering, nearest), texel, 0), scattered_last, valid, params.blend.x);
  const vec4 through = temporal_blend(texelFetch(sampler2D(fog_transmittance, nearest), texel, 0),
                                      vec4(through_last.rgb, scattered_last.a), valid, params.blend.x);
  imageStore(accumulated_scattering, texel, vec4(min(scattered.rgb, vec3(65000.0)), scattered.a));
  imageStore(accumulated_transmittance, texel, vec4(clamp(through.rgb, 0.0, 1.0), p.w));
}
