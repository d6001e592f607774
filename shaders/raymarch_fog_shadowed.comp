#version 450
#extension GL_GOOGLE_include_directive : require
// raymarch_fog with one light shadowed by a shadow map (set 1:
// include/fog_light_visibility.glsl). The march: shaders/include/raymarch_fog_body.glsl.
#define FOG_SHADOW_MAP
#include "include/fog_light_visibility.glsl"
#include "include/raymarch_fog_body.glsl"
