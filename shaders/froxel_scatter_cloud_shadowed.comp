#version 450
#extension GL_GOOGLE_include_directive : require
// froxel_scatter with the sun dimmed by the cloud layer above through a cloud_shadow_map, no
// shadow map (set 1: include/fog_light_visibility.glsl).
#define FOG_CLOUD_SHADOW
#include "include/fog_light_visibility.glsl"
#include "include/froxel_scatter_body.glsl"
