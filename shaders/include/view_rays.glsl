// The camera's rays by NDC, as passes/shading/camera.h `view_rays` packs them (std140):
// the ray through NDC (x, y) is forward + x·right + y·up, its component along forward 1,
// so the point at view depth z is position + z·ray. NDC y is up; pixel row 0 is y = 1.
#ifndef VOLGRAPH_VIEW_RAYS_GLSL
#define VOLGRAPH_VIEW_RAYS_GLSL

struct ViewRays {
  vec4 position;  // xyz; w unused
  vec4 forward;
  vec4 right;     // scaled by tan(fov/2)·aspect
  vec4 up;        // scaled by tan(fov/2)
};

vec3 view_ray(ViewRays v, vec2 ndc) { return v.forward.xyz + ndc.x * v.right.xyz + ndc.y * v.up.xyz; }

// NDC of texel `texel` (its centre plus `offset` texels) in a grid of `size` texels.
vec2 grid_ndc(vec2 texel, vec2 offset, vec2 size) {
  const vec2 uv = (texel + 0.5 + offset) / size;
  return vec2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
}

#endif
