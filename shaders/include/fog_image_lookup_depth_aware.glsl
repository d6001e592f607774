// fog_apply's depth-aware lookup, for techniques that ran below the frame's resolution:
// joint bilateral upsampling (Kopf, Cohen, Lischinski, Uyttendaele 2007) guided by the
// scene's depth. Each of the four image texels around the pixel is weighted bilinearly
// and by how close the view depth it was computed for (the farthest depth pixel it
// covers, as raymarch_fog marches) is to the pixel's own: w = w_bilinear /
// (DEPTH_TOLERANCE + |z_texel − z_pixel| / z_pixel). Across a silhouette a pixel takes
// the texels on its own side instead of smearing the other side's fog onto it.
#ifndef VOLGRAPH_FOG_IMAGE_LOOKUP_DEPTH_AWARE_GLSL
#define VOLGRAPH_FOG_IMAGE_LOOKUP_DEPTH_AWARE_GLSL
#include "depth_buffer.glsl"
#include "fog_apply_frame.h"

layout(set = 0, binding = 0) uniform texture2D fog_scattering;
layout(set = 0, binding = 1) uniform texture2D fog_transmittance;
layout(set = 0, binding = 2) uniform sampler nearest;
layout(set = 0, binding = 3) uniform FogApplyFrameBlock { FogApplyFrame frame; };
layout(set = 0, binding = 4) uniform texture2D scene_depth;

const float DEPTH_TOLERANCE = 0.01;  // relative depth difference at which a texel's weight halves

struct FogAtPixel {
  vec3 in_scatter;
  vec3 transmittance;
};

float view_depth_of(float depth) { return linear_view_depth(depth, frame.size.z, frame.size.w); }

FogAtPixel fog_at_pixel(vec2 frag_coord) {
  const ivec2 image_size = textureSize(sampler2D(fog_scattering, nearest), 0);
  const vec2 at = frag_coord * vec2(image_size) / frame.size.xy - 0.5;  // in image texels, centres at integers
  const ivec2 base = ivec2(floor(at));
  const vec2 f = at - vec2(base);
  const float pixel_z = view_depth_of(texelFetch(sampler2D(scene_depth, nearest), ivec2(frag_coord), 0).r);
  FogAtPixel fog = FogAtPixel(vec3(0.0), vec3(0.0));
  float total = 0.0;
  for (int k = 0; k < 4; ++k) {
    const ivec2 corner = ivec2(k & 1, k >> 1);
    const ivec2 texel = clamp(base + corner, ivec2(0), image_size - 1);
    const vec2 along = mix(1.0 - f, f, vec2(corner));
    const float texel_z = view_depth_of(covered_depth(scene_depth, nearest, texel, image_size));
    const float w = along.x * along.y / (DEPTH_TOLERANCE + abs(texel_z - pixel_z) / pixel_z);
    fog.in_scatter += w * texelFetch(sampler2D(fog_scattering, nearest), texel, 0).rgb;
    fog.transmittance += w * texelFetch(sampler2D(fog_transmittance, nearest), texel, 0).rgb;
    total += w;
  }
  fog.in_scatter /= total;
  fog.transmittance /= total;
  return fog;
}

#endif
