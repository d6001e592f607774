// The camera's rays by NDC, as physics/camera.h `view_rays` packs them (std140):
// the ray through NDC (x, y) is forward + x·right + y·up, its component along forward 1,
// so the point at view depth z is position + z·ray. NDC y is up; pixel row 0 is y = 1.
#ifndef VOLGRAPH_VIEW_RAYS_GLSL
#define VOLGRAPH_VIEW_RAYS_GLSL

#include "view_rays.h"  // struct ViewRays

vec3 view_ray(ViewRays v, vec2 ndc) { return v.forward.xyz + ndc.x * v.right.xyz + ndc.y * v.up.xyz; }

// NDC of texel `texel` (its centre plus `offset` texels) in a grid of `size` texels.
vec2 grid_ndc(vec2 texel, vec2 offset, vec2 size) {
  const vec2 uv = (texel + 0.5 + offset) / size;
  return vec2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
}

// Where world point p lies in the view — the inverse of view_ray: x, y its texture
// coordinate across the frame (u right, v down: pixel (i, j) of W × H at
// ((i + 0.5)/W, (j + 0.5)/H)), z its view depth (m; ≤ 0 behind the camera, where x and y
// mean nothing). The ray's right and up are orthogonal to forward, so
// ndc.x = (d·right)/(z·|right|²) for d = p − position. CPU twin: physics/camera.h.
vec3 view_uvz(ViewRays v, vec3 p) {
  const vec3 d = p - v.position.xyz;
  const float z = dot(d, v.forward.xyz);
  const vec2 along = vec2(dot(d, v.right.xyz) / dot(v.right.xyz, v.right.xyz), dot(d, v.up.xyz) / dot(v.up.xyz, v.up.xyz));
  const vec2 ndc = along / max(z, 1e-20);
  return vec3(0.5 + 0.5 * ndc.x, 0.5 - 0.5 * ndc.y, z);
}

#endif
