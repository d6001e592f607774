#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_aerial_perspective: the air's in-scattering with the sun dimmed by the clouds' shadow (cloud_shadow_map).
#define AERIAL_CLOUD_SHADOW
#include "include/atmosphere_aerial_perspective_body.glsl"
