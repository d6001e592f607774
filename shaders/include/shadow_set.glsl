// Set 2 of the passes that shade surfaces with one light shadowed by shadow_map's depth
// (scene_shadowed.frag): the map, its sampler and view, and the
// `light_visibility` surface_irradiance.glsl asks for. A view whose shadowed light index
// is −1 shadows nothing.
#ifndef VOLGRAPH_SHADOW_SET_GLSL
#define VOLGRAPH_SHADOW_SET_GLSL
#include "shadow_lookup.glsl"

layout(set = 2, binding = 0) uniform texture2D shadow_depth;
layout(set = 2, binding = 1) uniform sampler shadow_sampler;
layout(set = 2, binding = 2) uniform ShadowBlock { ShadowView view; } shadow;

float light_visibility(int light, vec3 p) {
  if (!shadows_light(shadow.view, light)) return 1.0;
  return shadow_visibility(shadow_depth, shadow_sampler, shadow.view, p);
}

#endif
