#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_shadow_map: the cloud layer's optical depth toward the sun, one coverage and type everywhere.
#include "include/cloud_shadow_map_body.glsl"
