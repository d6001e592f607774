#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_march: the cloud layer, coverage and type read from the weather map (cloud_layer.glsl); the phase read from cloud_phase_table (CLOUD_PHASE_TABLE).
#define CLOUD_WEATHER_MAP
#define CLOUD_PHASE_TABLE
#include "include/cloud_march_body.glsl"
