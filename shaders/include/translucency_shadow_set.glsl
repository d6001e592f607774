// Set 2 of the translucency pass's surface shaders: shadow_set.glsl's shadow map, and the
// translucent casters' map of the same light view (translucent_shadow_map's transmittance
// and nearest caster depth, bindings 5–6): a surface behind another translucent surface as
// the light sees it is lit through that surface's coloured transmittance (RTR4 §14.5.1), as
// the CPU reference's shadow rays cross translucent layers. The pass binds white stand-ins
// (transmittance 1, nothing in front) where no map is wired.
#ifndef VOLGRAPH_TRANSLUCENCY_SHADOW_SET_GLSL
#define VOLGRAPH_TRANSLUCENCY_SHADOW_SET_GLSL
#include "shadow_lookup.glsl"
#include "translucent_shadow_lookup.glsl"

layout(set = 2, binding = 0) uniform texture2D shadow_depth;
layout(set = 2, binding = 1) uniform sampler shadow_sampler;
layout(set = 2, binding = 2) uniform ShadowBlock { ShadowView view; } shadow;
layout(set = 2, binding = 5) uniform texture2D translucent_shadow;
layout(set = 2, binding = 6) uniform texture2D translucent_shadow_depth;

vec3 light_visibility(int light, vec3 p) {
  if (!shadows_light(shadow.view, light)) return vec3(1.0);
  return shadow_visibility(shadow_depth, shadow_sampler, shadow.view, p) *
         translucent_shadow_transmittance(translucent_shadow, translucent_shadow_depth, shadow_sampler, shadow.view, p);
}

#endif
