#version 450
#extension GL_GOOGLE_include_directive : require
// generate_mips, level 0 (passes/post/generate_mips.cpp): the input's texels, as they are.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D level;
layout(set = 0, binding = 2) uniform sampler nearest;

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(level)))) return;
  imageStore(level, texel, texelFetch(sampler2D(color, nearest), texel, 0));
}
