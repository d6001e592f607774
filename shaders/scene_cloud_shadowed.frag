#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque scene, no shadow map, the sun dimmed by the cloud layer above through a
// cloud_shadow_map (set 2, bindings 7–9).
#include "include/cloud_shadow_set.glsl"

float light_visibility(int light, vec3 p) { return cloud_visibility(light, p); }

#include "include/scene_shading.glsl"
