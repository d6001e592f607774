// What the light_volume pass's shaders share (passes/fog/light_volume.cpp): its
// parameter block, the layout of its light_frame image (the shadow map's clip space back
// to the world, written once per frame from the shadow map's view) and the camera ray of
// an image texel.
#ifndef VOLGRAPH_LIGHT_VOLUME_GLSL
#define VOLGRAPH_LIGHT_VOLUME_GLSL
#include "fog_frame.glsl"

#include "light_volume_params.h"  // struct LightVolumeParams

// light_frame: texels 0–3 the columns of the shadow map's clip space → world (the inverse
// of its view-projection), texel 4: x the sign of that map's orientation (its
// determinant), y the shadowed light's index (−1: none).
const int LIGHT_FRAME_TEXELS = 5;

mat4 light_clip_to_world(texture2D light_frame, sampler s) {
  return mat4(texelFetch(sampler2D(light_frame, s), ivec2(0, 0), 0), texelFetch(sampler2D(light_frame, s), ivec2(1, 0), 0),
              texelFetch(sampler2D(light_frame, s), ivec2(2, 0), 0), texelFetch(sampler2D(light_frame, s), ivec2(3, 0), 0));
}

// The camera ray of the fog image's texel at framebuffer position `frag_coord`, to the
// scene's surface: the depth of the frame pixel under the texel's centre.
PixelRay texel_ray(FogFrame f, LightVolumeParams p, vec2 frag_coord, texture2D scene_depth, sampler s) {
  const vec2 uv = frag_coord / vec2(p.sizes.zw);
  const ivec2 depth_size = textureSize(sampler2D(scene_depth, s), 0);
  const ivec2 pixel = min(ivec2(uv * vec2(depth_size)), depth_size - 1);
  return camera_ray(f, uv, texelFetch(sampler2D(scene_depth, s), pixel, 0).r);
}

#endif
