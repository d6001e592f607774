#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_noise (passes/clouds/cloud_noise.cpp): the curl texture, one texel an invocation, at
// its texel centre (shaders/include/cloud_noise.h: the text the CPU twin compiles too).
#include "include/cloud_noise.h"
#include "include/cloud_noise_params.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform CloudNoiseParamsBlock { CloudNoiseParams params; };
layout(set = 0, binding = 1, rgba8) uniform writeonly image2D curl;

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy), size = imageSize(curl);
  if (any(greaterThanEqual(texel, size))) return;
  imageStore(curl, texel, cloud_curl_texel((vec2(texel) + 0.5) / vec2(size), 1.0 / float(size.x), params.seed.x));
}
