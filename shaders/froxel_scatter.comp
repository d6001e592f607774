#version 450
#extension GL_GOOGLE_include_directive : require
// froxel_scatter without a shadow map: every light reaches every froxel.
float light_visibility(int light, vec3 p) { return 1.0; }
bool media_shadow_mapped(int light) { return false; }

#include "include/froxel_scatter_body.glsl"
