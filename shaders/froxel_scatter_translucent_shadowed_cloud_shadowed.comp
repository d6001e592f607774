#version 450
#extension GL_GOOGLE_include_directive : require
// froxel_scatter with one light shadowed by a shadow map and tinted by the translucent casters
// between it and each froxel through a translucent_shadow_map of the same light view (RTR4
// §14.5.1: the fog behind coloured glass carries its tint), and the sun dimmed by the cloud
// layer above through a cloud_shadow_map (set 1: include/fog_light_visibility.glsl).
#define FOG_SHADOW_MAP
#define FOG_TRANSLUCENT_SHADOW
#define FOG_CLOUD_SHADOW
#include "include/fog_light_visibility.glsl"
#include "include/froxel_scatter_body.glsl"
