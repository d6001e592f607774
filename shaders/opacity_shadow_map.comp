#version 450
#extension GL_GOOGLE_include_directive : require
// opacity_shadow_map: per texel column of the shadow map's light view, the local volumes'
// optical depth from the light to each layer's centre (include/opacity_shadow.glsl; the
// global and height fog are left to the closed form of light_transmittance.glsl):
// first the stretch from the column's start back toward the light, then layer by layer
// away from it, each by a march of equal steps (include/light_transmittance.glsl).
#include "include/fog_frame.glsl"
#include "include/light_transmittance.glsl"
#include "include/opacity_shadow.glsl"
#include "include/opacity_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform ShadowBlock { ShadowView view; } shadow;
layout(set = 0, binding = 2, rgba16f) uniform writeonly image3D optical_depth;
layout(set = 0, binding = 3) uniform OpacityParamsBlock { OpacityParams params; };

const float FP16_MAX = 65000.0;

void store(ivec3 texel, vec3 tau) { imageStore(optical_depth, texel, vec4(min(tau, vec3(FP16_MAX)), 0.0)); }

void main() {
  const ivec3 size = imageSize(optical_depth);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size.xy))) return;
  const int light_index = int(shadow.view.params.w);
  if (light_index < 0) {
    for (int k = 0; k < size.z; ++k) store(ivec3(texel, k), vec3(0.0));
    return;
  }
  const Light light = frame.f.light_list.lights[light_index];
  const MediaField media = local_volumes(frame.f.media);
  const vec2 ndc = vec2((float(texel.x) + 0.5) / float(size.x) * 2.0 - 1.0, 1.0 - (float(texel.y) + 0.5) / float(size.y) * 2.0);
  const LightColumn column = light_column(shadow.view, ndc);
  const float column_length = length(column.end - column.start);
  const vec3 away = (column.end - column.start) / column_length;  // the light's rays travel this way
  vec3 tau = optical_depth_along(media, column.start, -away, light_march_length(light, column.start, params.distances.x),
                                 params.steps.y, 0.5);
  const float layer = column_length / float(size.z);
  float reached = 0.0;
  for (int k = 0; k < size.z; ++k) {
    const float centre = (float(k) + 0.5) * layer;
    tau += optical_depth_along(media, column.start + reached * away, away, centre - reached, params.steps.x, 0.5);
    reached = centre;
    store(ivec3(texel, k), tau);
  }
}
