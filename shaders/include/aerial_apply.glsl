// aerial_perspective_apply's bindings and its lookup at a pixel: the scene's depth gives
// the surface's distance along the pixel's ray; pixels at the far plane (the sky, which
// holds the whole ray's air already) take nothing (T = 1, S = 0). Both draws read the same
// bind group (WebGPU requires the group to match each pipeline's layout exactly).
#ifndef VOLGRAPH_AERIAL_APPLY_GLSL
#define VOLGRAPH_AERIAL_APPLY_GLSL

#include "atmosphere_aerial_lookup.glsl"
#include "depth_buffer.glsl"

layout(set = 0, binding = 0) uniform Lookup { AerialLookup f; } lookup;
layout(set = 0, binding = 1) uniform texture2D scene_depth;
layout(set = 0, binding = 2) uniform texture3D aerial_scattering;
layout(set = 0, binding = 3) uniform texture3D aerial_transmittance;
layout(set = 0, binding = 4) uniform sampler trilinear;
layout(set = 0, binding = 5) uniform sampler nearest;

AerialAtPoint aerial_at_pixel(vec2 pixel) {
  const ivec2 size = textureSize(sampler2D(scene_depth, nearest), 0);
  const float depth = texelFetch(sampler2D(scene_depth, nearest), ivec2(pixel), 0).r;
  if (depth >= 1.0) return AerialAtPoint(vec3(0.0), vec3(1.0));
  const vec2 uv = (pixel + 0.5) / vec2(size);
  const vec3 ray = view_ray(lookup.f.view, vec2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0));
  const float t = linear_view_depth(depth, lookup.f.view.position.w, lookup.f.view.forward.w) * length(ray);
  return aerial_perspective_at(lookup.f, aerial_scattering, aerial_transmittance, trilinear, uv, t);
}

#endif
