// The fog techniques' `light_visibility` and `media_shadow_mapped` (the hooks of
// include/froxel_scatter_body.glsl and include/raymarch_fog_body.glsl) from the maps a
// permutation wires in set 1, chosen by the including shader's defines: FOG_SHADOW_MAP (the
// shadow map, bindings 0–2), FOG_MEDIA_SHADOW (the media's opacity map of its light view,
// 3–4), FOG_TRANSLUCENT_SHADOW (the translucent casters' map, 5–6; both need FOG_SHADOW_MAP)
// and FOG_CLOUD_SHADOW (cloud_shadow_map's optical depth toward the sun, 7–9). Each
// permutation is its defines and this file.
#ifndef VOLGRAPH_FOG_LIGHT_VISIBILITY_GLSL
#define VOLGRAPH_FOG_LIGHT_VISIBILITY_GLSL

#ifdef FOG_SHADOW_MAP
#include "shadow_lookup.glsl"
layout(set = 1, binding = 0) uniform texture2D shadow_depth;
layout(set = 1, binding = 1) uniform sampler shadow_sampler;
layout(set = 1, binding = 2) uniform ShadowBlock { ShadowView view; } shadow;
#endif
#ifdef FOG_MEDIA_SHADOW
#include "opacity_shadow.glsl"
layout(set = 1, binding = 3) uniform texture3D media_shadow;
layout(set = 1, binding = 4) uniform sampler media_shadow_sampler;
#endif
#ifdef FOG_TRANSLUCENT_SHADOW
#include "translucent_shadow_lookup.glsl"
layout(set = 1, binding = 5) uniform texture2D translucent_shadow;
layout(set = 1, binding = 6) uniform texture2D translucent_shadow_depth;
#endif
#ifdef FOG_CLOUD_SHADOW
#define CLOUD_SHADOW_SET 1
#include "cloud_shadow_set.glsl"
#endif

// The shadow map's light through what its light view holds: the depth test, the media's
// opacity map, the translucent casters' transmittance; every other light 1.
vec3 mapped_visibility(int light, vec3 p) {
  vec3 v = vec3(1.0);
#ifdef FOG_SHADOW_MAP
  if (!shadows_light(shadow.view, light)) return v;
  v *= shadow_visibility(shadow_depth, shadow_sampler, shadow.view, p);
#ifdef FOG_MEDIA_SHADOW
  v *= opacity_map_transmittance(media_shadow, media_shadow_sampler, shadow.view, p);
#endif
#ifdef FOG_TRANSLUCENT_SHADOW
  v *= translucent_shadow_transmittance(translucent_shadow, translucent_shadow_depth, shadow_sampler, shadow.view, p);
#endif
#endif
  return v;
}

vec3 light_visibility(int light, vec3 p) {
#ifdef FOG_CLOUD_SHADOW
  return mapped_visibility(light, p) * cloud_visibility(light, p);
#else
  return mapped_visibility(light, p);
#endif
}

// Whether light_visibility holds the media's transmittance toward `light` (no march for it).
bool media_shadow_mapped(int light) {
#ifdef FOG_MEDIA_SHADOW
  return shadows_light(shadow.view, light);
#else
  return false;
#endif
}

#endif
