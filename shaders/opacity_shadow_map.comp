#version 450
#extension GL_GOOGLE_include_directive : require
// opacity_shadow_map: per texel column of the shadow map's light view, the local volumes'
// optical depth from the light to each layer's centre (include/opacity_shadow.glsl; the
// global and height fog are left to the closed form of light_transmittance.glsl):
// first the stretch from the column's start back toward the light, then layer by layer
// away from it, each by a march of equal steps (include/light_transmittance.glsl). Regular
// layers span the column evenly; deep ones (Yuksel & Keyser 2008) start at the column's
// first medium, found from the volumes' shapes (include/media_average.glsl volume_interval),
// Δ apart. Layer 0's alpha records the layers' start, every other layer's their span
// (include/opacity_shadow.glsl OpacityLayerPlacement).
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

void store(ivec3 texel, vec3 tau, OpacityLayerPlacement placement) {
  imageStore(optical_depth, texel, vec4(min(tau, vec3(FP16_MAX)), texel.z == 0 ? placement.start : placement.span));
}

// Where the column (from `start`, `len` m along unit `away`) first enters a local volume's
// shape, in metres from its start, clamped to [0, len]; 0 where it meets none: the deep
// map's depth pass (Yuksel & Keyser 2008, sec. 3.1), from the shapes rather than a density
// march — exact at any resolution, one interval per volume (a noisy volume's shape bounds
// its medium, so its empty margins count as medium).
float first_medium_depth(MediaField media, vec3 start, vec3 away, float len) {
  float first = len;
  for (int i = 0; i < media.counts.x; ++i) {
    const vec2 chord = volume_interval(media.volumes[i], start, away);
    if (chord.x <= chord.y && chord.y > 0.0 && chord.x < len) first = min(first, max(chord.x, 0.0));
  }
  return first < len ? first : 0.0;
}

void main() {
  const ivec3 size = imageSize(optical_depth);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size.xy))) return;
  const int light_index = int(shadow.view.params.w);
  if (light_index < 0) {
    for (int k = 0; k < size.z; ++k) store(ivec3(texel, k), vec3(0.0), OpacityLayerPlacement(0.0, 1.0));
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
  const bool deep = params.steps.z != 0;
  const float layer = deep ? params.distances.y : column_length / float(size.z);
  // Layer k's centre lies (k + 0.5)·layer + origin m from the column's start.
  const float origin = deep ? first_medium_depth(media, column.start, away, column_length) - 0.5 * layer : 0.0;
  const OpacityLayerPlacement placement = deep ? OpacityLayerPlacement(origin / column_length, float(size.z) * layer / column_length)
                                               : OpacityLayerPlacement(0.0, 1.0);
  float reached = 0.0;
  for (int k = 0; k < size.z; ++k) {
    const float centre = (float(k) + 0.5) * layer + origin;
    tau += optical_depth_along(media, column.start + reached * away, away, centre - reached, params.steps.x, 0.5);
    reached = centre;
    store(ivec3(texel, k), tau, placement);
  }
}
