#version 450
#extension GL_GOOGLE_include_directive : require
// generate_mips, level k from level k − 1 (passes/post/generate_mips.cpp; RTR4 6.2.2): each
// texel the mean of the texels above it covers — 2 per axis, 3 along an odd side's last
// texel (so no texel of the level above is dropped), a box over the stored values.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba16f) uniform readonly image2D above;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D level;

// The texels of the level above that texel t covers along one axis: [2t, 2t + count).
int covered(int t, int size_above, int size) { return (t == size - 1 && size_above > 2 * size) ? size_above - 2 * t : min(2, size_above - 2 * t); }

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const ivec2 size = imageSize(level), size_above = imageSize(above);
  if (any(greaterThanEqual(texel, size))) return;
  const ivec2 count = ivec2(covered(texel.x, size_above.x, size.x), covered(texel.y, size_above.y, size.y));
  vec4 sum = vec4(0.0);
  for (int j = 0; j < count.y; ++j) {
    for (int i = 0; i < count.x; ++i) sum += imageLoad(above, 2 * texel + ivec2(i, j));
  }
  imageStore(level, texel, sum / float(count.x * count.y));
}
