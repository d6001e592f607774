// froxel_apply's lookup: the integrated in-scattering and transmittance from the camera
// to a pixel's surface, read trilinearly from scatter_integrate's volumes at the pixel's
// view depth. Slice k's texel holds the integral to the slice's far edge, so depth w
// (slice coordinate) reads at w − ½/N; in front of the first slice's far edge the
// values ramp linearly from the camera (nothing, full transmittance).
#ifndef VOLGRAPH_FROXEL_LOOKUP_GLSL
#define VOLGRAPH_FROXEL_LOOKUP_GLSL
#include "fog_frame.glsl"

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture2D scene_depth;
layout(set = 0, binding = 2) uniform texture3D integrated_scattering;
layout(set = 0, binding = 3) uniform texture3D integrated_transmittance;
layout(set = 0, binding = 4) uniform sampler trilinear;
layout(set = 0, binding = 5) uniform sampler nearest;

struct FogAtPixel {
  vec3 in_scatter;
  vec3 transmittance;
};

FogAtPixel fog_at_pixel(vec2 pixel) {
  const ivec2 size = textureSize(sampler2D(scene_depth, nearest), 0);
  const float depth = texelFetch(sampler2D(scene_depth, nearest), ivec2(pixel), 0).r;
  const float slices = float(frame.f.grid.size.z);
  const float w = froxel_w(frame.f.grid, view_depth(frame.f, depth));
  const float ramp = clamp(w * slices, 0.0, 1.0);
  const vec3 uvw = vec3((pixel + 0.5) / vec2(size), max(w - 0.5 / slices, 0.5 / slices));
  FogAtPixel fog;
  fog.in_scatter = texture(sampler3D(integrated_scattering, trilinear), uvw).rgb * ramp;
  fog.transmittance = 1.0 - (1.0 - texture(sampler3D(integrated_transmittance, trilinear), uvw).rgb) * ramp;
  return fog;
}

#endif
