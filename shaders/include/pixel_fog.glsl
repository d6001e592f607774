// The per-pixel fog techniques' common part (passes/fog/pixel_fog.h): bindings 0–4, each
// output texel's camera ray up to the scene's surface (or the far plane where nothing
// was drawn), and the store of the two images. The including shader declares its own
// Params block at binding 5.
#ifndef VOLGRAPH_PIXEL_FOG_GLSL
#define VOLGRAPH_PIXEL_FOG_GLSL
#include "fog_frame.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture2D scene_depth;
layout(set = 0, binding = 2) uniform sampler nearest;
layout(set = 0, binding = 3, rgba16f) uniform writeonly image2D fog_scattering;
layout(set = 0, binding = 4, rgba16f) uniform writeonly image2D fog_transmittance;

const float FP16_MAX = 65000.0;  // stored values are clamped below rgba16f's largest

// The ray of output texel `texel` (false outside the image). A lower-resolution image
// reads the depth of the frame pixel under its texel's centre.
bool pixel_ray(uvec2 texel, out PixelRay ray) {
  const ivec2 size = imageSize(fog_scattering);
  if (any(greaterThanEqual(texel, uvec2(size)))) return false;
  const ivec2 depth_size = textureSize(sampler2D(scene_depth, nearest), 0);
  const vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  const ivec2 pixel = min(ivec2(uv * vec2(depth_size)), depth_size - 1);
  ray = camera_ray(frame.f, uv, texelFetch(sampler2D(scene_depth, nearest), pixel, 0).r);
  return true;
}

void store_fog(uvec2 texel, vec3 scattering, vec3 transmittance) {
  imageStore(fog_scattering, ivec2(texel), vec4(clamp(scattering, vec3(0.0), vec3(FP16_MAX)), 0.0));
  imageStore(fog_transmittance, ivec2(texel), vec4(clamp(transmittance, vec3(0.0), vec3(1.0)), 0.0));
}

#endif
