#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque scene with one light shadowed by a shadow map (set 2).
#include "include/shadow_set.glsl"
#include "include/scene_shading.glsl"
