#version 450
#extension GL_GOOGLE_include_directive : require
// light_shafts_screen (passes/fog/light_shafts_screen.cpp): Mitchell 2007's radial blur
// (GPU Gems 3 ch. 13; RTR4 §14.2.2). Each pixel steps `samples` times toward the sun's
// position on the frame over `density` of the way, summing the occlusion mask (1 where the
// scene's depth holds nothing: the sky) × weight × decayⁱ; × the sun's irradiance × exposure
// × the fade as the sun leaves the frame. Written as fog_apply's pair: in-scattered radiance
// and a transmittance of 1 (the shafts add light, they dim nothing).
#include "include/light_shafts_params.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform LightShaftsBlock { LightShaftsParams params; };
layout(set = 0, binding = 1) uniform texture2D scene_depth;
layout(set = 0, binding = 2) uniform sampler nearest;
layout(set = 0, binding = 3, rgba16f) uniform writeonly image2D fog_scattering;
layout(set = 0, binding = 4, rgba16f) uniform writeonly image2D fog_transmittance;

const float HALF_MAX = 65504.0;

// The occlusion mask at texture coordinate uv (clamped to the frame): 1 for the sky.
float sky_at(vec2 uv, ivec2 size) {
  const ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
  return texelFetch(sampler2D(scene_depth, nearest), texel, 0).r >= 1.0 ? 1.0 : 0.0;
}

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy), size = imageSize(fog_scattering);
  if (any(greaterThanEqual(texel, size))) return;
  vec3 shafts = vec3(0.0);
  if (params.sun.z > 0.0) {
    const ivec2 depth_size = textureSize(sampler2D(scene_depth, nearest), 0);
    const int samples = int(params.march.x);
    const vec2 uv = (vec2(texel) + 0.5) / vec2(size);
    const vec2 step_uv = (uv - params.sun.xy) * params.march.y / float(samples);
    vec2 at = uv;
    float decay = 1.0, gathered = 0.0;
    for (int i = 0; i < samples; ++i) {
      at -= step_uv;
      gathered += sky_at(at, depth_size) * decay * params.march.z;
      decay *= params.march.w;
    }
    shafts = min(gathered * params.radiance.rgb, vec3(HALF_MAX));
  }
  imageStore(fog_scattering, texel, vec4(shafts, 1.0));
  imageStore(fog_transmittance, texel, vec4(1.0));
}
