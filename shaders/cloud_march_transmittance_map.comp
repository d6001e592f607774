#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_march's transmittance_map variant: the sun's optical depth read from cloud_shadow_map's transmittance map.
#define CLOUD_TRANSMITTANCE_MAP
#include "include/cloud_march_body.glsl"
