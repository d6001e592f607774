#version 450
#extension GL_GOOGLE_include_directive : require
// froxel_scatter with one light shadowed by a shadow map and by the media through an opacity
// shadow map of the same light view, and the sun dimmed by the cloud layer above through a
// cloud_shadow_map (set 1: include/froxel_scatter_visibility.glsl).
#define FROXEL_SHADOW_MAP
#define FROXEL_MEDIA_SHADOW
#define FROXEL_CLOUD_SHADOW
#include "include/froxel_scatter_visibility.glsl"
#include "include/froxel_scatter_body.glsl"
