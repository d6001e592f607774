#version 450
#extension GL_GOOGLE_include_directive : require
// cube_mips, level k from level k − 1, face by face (passes/post/cube_mips.cpp; RTR4 10.5.1's
// mip-mapped environment): each texel the mean of the 2 × 2 texels of its face above it (3
// along an odd side's last texel), as generate_mips does for an image; faces are filtered
// apart (no seam blending across their edges).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0, rgba16f) uniform readonly image2DArray above;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2DArray level;

// The texels of the level above that texel t covers along one axis: [2t, 2t + count).
int covered(int t, int size_above, int size) { return (t == size - 1 && size_above > 2 * size) ? size_above - 2 * t : min(2, size_above - 2 * t); }

void main() {
  const ivec3 texel = ivec3(gl_GlobalInvocationID);
  const ivec3 size = imageSize(level), size_above = imageSize(above);
  if (any(greaterThanEqual(texel, size))) return;
  const ivec2 count = ivec2(covered(texel.x, size_above.x, size.x), covered(texel.y, size_above.y, size.y));
  vec4 sum = vec4(0.0);
  for (int j = 0; j < count.y; ++j) {
    for (int i = 0; i < count.x; ++i) sum += imageLoad(above, ivec3(2 * texel.xy + ivec2(i, j), texel.z));
  }
  imageStore(level, texel, sum / float(count.x * count.y));
}
