#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_shadow_map: the cloud layer's optical depth toward the sun, coverage and type read from the weather map (cloud_layer.glsl).
#define CLOUD_WEATHER_MAP
#include "include/cloud_shadow_map_body.glsl"
