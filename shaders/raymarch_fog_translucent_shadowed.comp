#version 450
#extension GL_GOOGLE_include_directive : require
// raymarch_fog with one light shadowed by a shadow map and tinted by the translucent casters
// between it and each sample through a translucent_shadow_map of the same light view (RTR4
// §14.5.1) (set 1: include/fog_light_visibility.glsl). The march:
// shaders/include/raymarch_fog_body.glsl.
#define FOG_SHADOW_MAP
#define FOG_TRANSLUCENT_SHADOW
#include "include/fog_light_visibility.glsl"
#include "include/raymarch_fog_body.glsl"
