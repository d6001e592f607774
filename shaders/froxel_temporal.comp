#version 450
#extension GL_GOOGLE_include_directive : require
// froxel_temporal (Hillaire 2015, p. 9): temporal accumulation of the froxel
// in-scattering volume. Each froxel's centre, in this frame's grid, is reprojected into
// the last frame's grid (froxel_uvw with the last frame's view); last frame's blended
// volume is read there trilinearly and blended with this frame's value
// (temporal_blend.glsl). Where the last frame's grid did not reach, and on the first
// frame, this frame's value passes through unchanged (passes/fog/froxel_temporal.cpp).
#include "include/fog_frame.glsl"
#include "include/temporal_blend.glsl"
#include "include/temporal_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture3D in_scatter;
layout(set = 0, binding = 2) uniform texture3D history;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4) uniform sampler trilinear;  // linear filtering: trilinear in a 3D texture
layout(set = 0, binding = 5, rgba16f) uniform writeonly image3D accumulated;
layout(set = 0, binding = 6) uniform TemporalParamsBlock { TemporalParams params; };

void main() {
  const uvec3 id = gl_GlobalInvocationID;
  if (any(greaterThanEqual(id, frame.f.grid.size.xyz))) return;
  const vec4 current = texelFetch(sampler3D(in_scatter, nearest), ivec3(id), 0);
  vec4 where = vec4((vec3(id) + 0.5) / vec3(frame.f.grid.size.xyz), 1.0);
  if (params.blend.z > 0.5) where = froxel_uvw(params.previous_view, frame.f.grid, froxel_position(frame.f, vec3(id), vec3(0.0)));
  const bool valid = params.blend.y > 0.5 && where.w > 0.5;
  const vec4 last = valid ? texture(sampler3D(history, trilinear), where.xyz) : vec4(0.0);
  const vec4 blended = temporal_blend(current, last, valid, params.blend.x);
  imageStore(accumulated, ivec3(id), vec4(min(blended.rgb, vec3(65000.0)), blended.a));
}
