// The cloud-shadow bindings (set CLOUD_SHADOW_SET: the scene's 2, froxel_scatter's 1; after
// the shadow maps' 0–6): cloud_shadow_map's optical depth, a linear sampler and its view, and `cloud_visibility`: exp(−τ) for the sun
// the map was made for, 1 for every other light.
#ifndef VOLGRAPH_CLOUD_SHADOW_SET_GLSL
#define VOLGRAPH_CLOUD_SHADOW_SET_GLSL
#include "cloud_shadow_lookup.glsl"

#ifndef CLOUD_SHADOW_SET
#define CLOUD_SHADOW_SET 2  // the scene's; froxel_scatter's is 1
#endif

layout(set = CLOUD_SHADOW_SET, binding = 7) uniform texture2D cloud_shadow;
layout(set = CLOUD_SHADOW_SET, binding = 8) uniform sampler cloud_shadow_sampler;
layout(set = CLOUD_SHADOW_SET, binding = 9) uniform CloudShadowBlock { CloudShadowView view; } cloud_shadow_view;

float cloud_visibility(int light, vec3 p) {
  if (light != int(cloud_shadow_view.view.to_sun.w)) return 1.0;
  return cloud_shadow_transmittance(cloud_shadow, cloud_shadow_sampler, cloud_shadow_view.view, p);
}

#endif
