// Reading the scene pass's depth buffer (perspective, depth 0 at the near plane and 1 at
// the far one; DESIGN.md), shared by the passes that sample it.
#ifndef VOLGRAPH_DEPTH_BUFFER_GLSL
#define VOLGRAPH_DEPTH_BUFFER_GLSL

// View depth (m) of a depth-buffer value: near·far / (far − d·(far − near)).
float linear_view_depth(float depth, float near, float far) { return near * far / (far - depth * (far - near)); }

// The depth-buffer value behind texel `texel` of an image of `image_size` over the same
// frame: the farthest of the depth pixels it covers (one at full resolution, 2×2 at
// half), so a lower-resolution technique reaches the background wherever any of them
// sees it.
float covered_depth(texture2D depth, sampler nearest, ivec2 texel, ivec2 image_size) {
  const ivec2 depth_size = textureSize(sampler2D(depth, nearest), 0);
  const ivec2 first = texel * depth_size / image_size;
  const ivec2 last = max(first, ((texel + 1) * depth_size - 1) / image_size);
  float farthest = 0.0;
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) farthest = max(farthest, texelFetch(sampler2D(depth, nearest), ivec2(x, y), 0).r);
  }
  return farthest;
}

#endif
