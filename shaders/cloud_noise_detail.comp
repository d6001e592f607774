#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_noise (passes/clouds/cloud_noise.cpp): the detail texture, one texel an invocation, at
// its texel centre (shaders/include/cloud_noise.h: the text the CPU twin compiles too).
#include "include/cloud_noise.h"
#include "include/cloud_noise_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform CloudNoiseParamsBlock { CloudNoiseParams params; };
layout(set = 0, binding = 1, rgba8) uniform writeonly image3D detail;

void main() {
  const ivec3 texel = ivec3(gl_GlobalInvocationID.xyz), size = imageSize(detail);
  if (any(greaterThanEqual(texel, size))) return;
  imageStore(detail, texel, cloud_detail_texel((vec3(texel) + 0.5) / vec3(size), params.seed.x));
}
