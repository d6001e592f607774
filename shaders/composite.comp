#version 450
// Composite: exposure and tone map of linear radiance into the frame's output
// (passes/composite.cpp). Separate texture and sampler, uniform block: WebGPU-safe.
#extension GL_GOOGLE_include_directive : require
#include "include/tonemap.glsl"
#include "include/composite_params.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;
layout(set = 0, binding = 1) uniform sampler nearest;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D frame;
layout(set = 0, binding = 3) uniform CompositeParamsBlock { CompositeParams params; };

void main() {
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, params.size))) return;
  const vec4 radiance = texelFetch(sampler2D(color, nearest), ivec2(pixel), 0);
  imageStore(frame, ivec2(pixel), vec4(tone_map(radiance.rgb, params.exposure_ev, params.tone_map_op), 1.0));
}
