// What froxel_voxelize tells the other fog passes of the frame (its `frame` buffer,
// std140, packed by passes/fog/fog_frame.cpp): the camera's rays, the froxel grid, this
// frame's sample jitter, ambient radiance, the lights and the media.
#ifndef VOLGRAPH_FOG_FRAME_GLSL
#define VOLGRAPH_FOG_FRAME_GLSL
#include "depth_buffer.glsl"
#include "froxel.glsl"
#include "light_list.glsl"
#include "media_field.glsl"
#include "view_rays.glsl"

#include "fog_frame.h"  // struct FogFrame

// View depth of a depth-buffer value of the scene pass's camera.
float view_depth(FogFrame f, float depth) { return linear_view_depth(depth, f.view.position.w, f.view.forward.w); }

// A camera ray up to the scene's surface (or the far plane where nothing was drawn).
struct PixelRay {
  vec3 origin;
  vec3 direction;  // unit
  float len;       // m, along the ray to the surface or the far plane
};

// The ray through image coordinate `uv` ([0, 1]², row 0 at the top) that ends at the
// scene depth-buffer value `depth`.
PixelRay camera_ray(FogFrame f, vec2 uv, float depth) {
  const vec3 through = view_ray(f.view, vec2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0));
  const float ray_scale = length(through);
  return PixelRay(f.view.position.xyz, through / ray_scale, view_depth(f, depth) * ray_scale);
}

// World position of froxel `texel` (plus `offset` froxels) of the grid.
vec3 froxel_position(FogFrame f, vec3 texel, vec3 offset) {
  const vec3 size = vec3(f.grid.size.xyz);
  const vec2 ndc = grid_ndc(texel.xy, offset.xy, size.xy);
  const float depth = froxel_depth(f.grid, (texel.z + 0.5 + offset.z) / size.z);
  return f.view.position.xyz + depth * view_ray(f.view, ndc);
}

#endif
