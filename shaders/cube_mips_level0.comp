#version 450
#extension GL_GOOGLE_include_directive : require
// cube_mips, level 0 (passes/post/cube_mips.cpp): the input cube toward each texel's centre
// (include/cube_face.h), bilinear: any input size; at the input's own size, its texels.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

#include "include/cube_face.h"

layout(set = 0, binding = 0) uniform textureCube cube;
layout(set = 0, binding = 1) uniform sampler linear;
layout(set = 0, binding = 2, rgba16f) uniform writeonly image2DArray level;

void main() {
  const ivec3 texel = ivec3(gl_GlobalInvocationID);
  const ivec3 size = imageSize(level);
  if (any(greaterThanEqual(texel, size))) return;
  const vec3 direction = cube_texel_direction(texel.z, texel.xy, size.x);
  imageStore(level, texel, vec4(textureLod(samplerCube(cube, linear), direction, 0.0).rgb, 1.0));
}
