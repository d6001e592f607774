// froxel_apply's lookup: the integrated in-scattering and transmittance from the camera
// to a pixel's surface (froxel_sample.glsl at the pixel's view depth).
#ifndef VOLGRAPH_FROXEL_LOOKUP_GLSL
#define VOLGRAPH_FROXEL_LOOKUP_GLSL
#include "froxel_sample.glsl"

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture2D scene_depth;
layout(set = 0, binding = 2) uniform texture3D integrated_scattering;
layout(set = 0, binding = 3) uniform texture3D integrated_transmittance;
layout(set = 0, binding = 4) uniform sampler trilinear;
layout(set = 0, binding = 5) uniform sampler nearest;

FogAtPixel fog_at_pixel(vec2 pixel) {
  const ivec2 size = textureSize(sampler2D(scene_depth, nearest), 0);
  const float depth = texelFetch(sampler2D(scene_depth, nearest), ivec2(pixel), 0).r;
  return froxel_fog_at(frame.f, integrated_scattering, integrated_transmittance, trilinear, (pixel + 0.5) / vec2(size),
                       view_depth(frame.f, depth));
}

#endif
