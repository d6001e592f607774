#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_march's transmittance_map variant: the sun's optical depth read from cloud_shadow_map's transmittance map; the phase read from cloud_phase_table (CLOUD_PHASE_TABLE).
#define CLOUD_TRANSMITTANCE_MAP
#define CLOUD_PHASE_TABLE
#include "include/cloud_march_body.glsl"
