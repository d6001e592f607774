// fog_apply's lookup: the in-scattered radiance and transmittance a per-pixel fog
// technique (raymarch_fog, analytic_fog, height_fog, depth_fog…) wrote into two images,
// read bilinearly at the pixel's centre, so a half-resolution technique upsamples. Both
// draws read both images, so their pipelines share one bind group layout (WebGPU
// requires the group to match each pipeline's layout exactly).
#ifndef VOLGRAPH_FOG_IMAGE_LOOKUP_GLSL
#define VOLGRAPH_FOG_IMAGE_LOOKUP_GLSL

layout(set = 0, binding = 0) uniform texture2D fog_scattering;
layout(set = 0, binding = 1) uniform texture2D fog_transmittance;
layout(set = 0, binding = 2) uniform sampler bilinear;
#include "fog_apply_frame.h"
layout(set = 0, binding = 3) uniform FogApplyFrameBlock { FogApplyFrame frame; };

struct FogAtPixel {
  vec3 in_scatter;
  vec3 transmittance;
};

FogAtPixel fog_at_pixel(vec2 frag_coord) {
  const vec2 uv = frag_coord / frame.size.xy;
  FogAtPixel fog;
  fog.in_scatter = texture(sampler2D(fog_scattering, bilinear), uv).rgb;
  fog.transmittance = texture(sampler2D(fog_transmittance, bilinear), uv).rgb;
  return fog;
}

#endif
