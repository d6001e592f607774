// The froxel grid: a camera-frustum volume of size.x × size.y texels on screen and
// size.z slices in view depth from range.x (near) to range.y (far), spaced linearly
// (range.z = 0) or exponentially (range.z = 1). Slice coordinate w ∈ [0, 1] maps to view
// depth. CPU twin: passes/shading/froxel.h.
#ifndef VOLGRAPH_FROXEL_GLSL
#define VOLGRAPH_FROXEL_GLSL

struct FroxelGrid {
  uvec4 size;   // xyz froxels, w unused
  vec4 range;   // x near, y far (view depth, m), z distribution (0 linear, 1 exponential)
};

float froxel_depth(FroxelGrid g, float w) {
  if (g.range.z < 0.5) return mix(g.range.x, g.range.y, w);
  return g.range.x * pow(g.range.y / g.range.x, w);
}

// The slice coordinate of view depth z, clamped to [0, 1].
float froxel_w(FroxelGrid g, float z) {
  if (g.range.z < 0.5) return clamp((z - g.range.x) / (g.range.y - g.range.x), 0.0, 1.0);
  return clamp(log(max(z, g.range.x) / g.range.x) / log(g.range.y / g.range.x), 0.0, 1.0);
}

#endif
