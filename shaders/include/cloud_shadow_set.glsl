// The scene's cloud-shadow bindings (set 2, after the shadow map's 0–6): cloud_shadow_map's
// optical depth, a linear sampler and its view, and `cloud_visibility`: exp(−τ) for the sun
// the map was made for, 1 for every other light.
#ifndef VOLGRAPH_CLOUD_SHADOW_SET_GLSL
#define VOLGRAPH_CLOUD_SHADOW_SET_GLSL
#include "cloud_shadow_lookup.glsl"

layout(set = 2, binding = 7) uniform texture2D cloud_shadow;
layout(set = 2, binding = 8) uniform sampler cloud_shadow_sampler;
layout(set = 2, binding = 9) uniform CloudShadowBlock { CloudShadowView view; } cloud_shadow_view;

float cloud_visibility(int light, vec3 p) {
  if (light != int(cloud_shadow_view.view.to_sun.w)) return 1.0;
  return cloud_shadow_transmittance(cloud_shadow, cloud_shadow_sampler, cloud_shadow_view.view, p);
}

#endif
