#version 450
#extension GL_GOOGLE_include_directive : require
// froxel_scatter with the sun dimmed by the cloud layer above through a cloud_shadow_map, no
// shadow map (set 1: include/froxel_scatter_visibility.glsl).
#define FROXEL_CLOUD_SHADOW
#include "include/froxel_scatter_visibility.glsl"
#include "include/froxel_scatter_body.glsl"
