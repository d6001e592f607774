// The froxel grid: a camera-frustum volume of size.x × size.y texels on screen and
// size.z slices in view depth from range.x (near) to range.y (far), spaced linearly
// (range.z = 0) or exponentially (range.z = 1). Slice coordinate w ∈ [0, 1] maps to view
// depth. CPU twin: physics/froxel.h.
#ifndef VOLGRAPH_FROXEL_GLSL
#define VOLGRAPH_FROXEL_GLSL
#include "view_rays.glsl"

#include "froxel_grid.h"  // struct FroxelGrid

float froxel_depth(FroxelGrid g, float w) {
  if (g.range.z < 0.5) return mix(g.range.x, g.range.y, w);
  return g.range.x * pow(g.range.y / g.range.x, w);
}

// The slice coordinate of view depth z, clamped to [0, 1].
float froxel_w(FroxelGrid g, float z) {
  if (g.range.z < 0.5) return clamp((z - g.range.x) / (g.range.y - g.range.x), 0.0, 1.0);
  return clamp(log(max(z, g.range.x) / g.range.x) / log(g.range.y / g.range.x), 0.0, 1.0);
}

// Where world point p falls in grid g of view v, as a texture coordinate of the grid's
// volumes (xyz: u, v across the frame, the slice coordinate w; a froxel's centre sits at
// its texel's centre) and w = 1 inside the grid (in front of the camera, within the
// frame, view depth in [near, far]), 0 outside. Hillaire 2015 (p. 9) reads the previous
// frame's scattering volume there, with the previous frame's view, to blend it with this
// frame's: the reprojection of temporal accumulation.
vec4 froxel_uvw(ViewRays v, FroxelGrid g, vec3 p) {
  const vec3 uvz = view_uvz(v, p);
  const bool inside = all(greaterThanEqual(uvz.xy, vec2(0.0))) && all(lessThanEqual(uvz.xy, vec2(1.0))) &&
                      uvz.z >= g.range.x && uvz.z <= g.range.y;
  return vec4(uvz.xy, froxel_w(g, uvz.z), inside ? 1.0 : 0.0);
}

#endif
